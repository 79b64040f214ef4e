#pragma once
// Where this process hosts a virtualcan bus.
//
// Qt's virtualcan plugin (6.4) keeps one bus server per process (a TCP server on 127.0.0.1),
// started by the first device that connects, on that device's thread, and never stopped. When
// that thread ends (a CAN master's thread after a failed start or a reconnect) the port stays
// listening with nobody to accept: clients that come later (a drive simulator started
// afterwards) wait in the backlog until the program ends. hostVirtualCanBus() makes the attempt
// to host from a thread that lives as long as the process; call it before connecting a device on
// a thread that may end. A no-op for other plugins and for a bus on another host.
//
// The bus is hosted by CutCell's own relay (same protocol and port as the plugin's server, which
// then finds the port taken and stays idle): it relays only well-formed lines
// (virtualcan_wire.h) and drops and logs the rest under cutcell.canopen.relay - one malformed
// line relayed by Qt's server crashes every Qt client on the bus.
//
// Threading contract: any thread; blocks the caller for the moment the host thread needs to try
// (listen on a local port) - never for the bus.
#include <QString>

namespace cutcell::canopen {

void hostVirtualCanBus(const QString& plugin, const QString& interface);

} // namespace cutcell::canopen
