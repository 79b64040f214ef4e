#pragma once
// Composition glue: the CAN master's snapshot as the device panel's plain snapshot (app/ is the
// only place that knows both devices/ and ui/). Call from the GUI timer; snapshot() takes a
// short mutex in the master, never waits on the bus.
#include "devices/canopen/canopen_master.h"
#include "devices/canopen/emcy.h"
#include "ui/device_panel.h"

namespace cutcell::app {

inline ui::DevicePanelSnapshot toPanelSnapshot(const canopen::CanBusSnapshot& s,
                                               const std::vector<QString>& axisNames) {
    using namespace cutcell::canopen;
    ui::DevicePanelSnapshot p;
    p.can = true;
    p.bus_state = QString::fromStdString(s.bus_text.empty() ? toString(s.bus) : s.bus_text);
    p.bus_error = s.bus == BusState::BusOff || s.bus == BusState::Disconnected ||
                  s.bus == BusState::ErrorPassive;
    p.load = s.load;
    p.load_text = QString::fromStdString(s.load_text);
    for (size_t i = 0; i < s.nodes.size(); ++i) {
        const CanNodeSnapshot& n = s.nodes[i];
        ui::DevicePanelNode r;
        r.node = n.node;
        r.axis = i < axisNames.size() ? axisNames[i] : QString::number(i);
        r.nmt = QString::fromLatin1(toString(n.nmt));
        r.cia402 = QString::fromLatin1(toString(n.state));
        r.heartbeat_age_ms = n.heartbeat_age_ms;
        r.last_emcy = QString::fromStdString(n.last_emcy_text);
        r.fault = QString::fromStdString(n.fault_text);
        r.error = n.fault_code != 0 || n.state == Cia402State::Fault || !n.last_emcy_text.empty();
        p.nodes.push_back(std::move(r));
    }
    return p;
}

} // namespace cutcell::app
