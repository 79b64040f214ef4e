#pragma once
// Checks and settings of a Qt SerialBus CAN device shared by the master and the drive simulator.
#include <QString>

#include <string>

class QCanBusDevice;

namespace cutcell::canopen {

// True when `plugin` exists and offers `interface` (QCanBus::availableDevices); else false with
// the reason, naming what the plugin offers, e.g. "CAN interface \"can5\" is not offered by
// plugin virtualcan; it offers: can0, can1". virtualcan also takes a URL
// (tcp://127.0.0.1:PORT/can0): its last path element is the interface.
bool checkCanInterface(const QString& plugin, const QString& interface, std::string* error);

// Sets TCP_NODELAY (QAbstractSocket::LowDelayOption) on the TCP sockets a connected device uses
// (virtualcan's client socket is a child QTcpSocket of the device). Without it Nagle holds a
// small frame written right after another until the peer's delayed ACK (~40 ms). When this
// process hosts the virtualcan bus (its first client was here), the bus server's sockets in
// this process get it too: the listening socket (accepted clients inherit it on Linux) and the
// clients already accepted - the server forwards every frame and would hold them likewise.
// Returns the number of sockets set; 0 for transports without one (socketcan).
int setLowDelay(QCanBusDevice* device, const QString& plugin, const QString& interface);

// Writes what the device buffered to its socket now (virtualcan), instead of at the next
// return to the event loop. No-op for other transports.
void flushDevice(QCanBusDevice* device);

} // namespace cutcell::canopen
