#pragma once
// Composition glue: the CAN master's snapshot as the device panel's plain snapshot (app/ is the
// only place that knows both devices/ and ui/). Call from the GUI timer; snapshot() takes a
// short mutex in the master, never waits on the bus.
#include "devices/canopen/canopen_master.h"
#include "devices/canopen/emcy.h"
#include "ui/device_panel.h"
#include "ui/engine_rig.h"

namespace cutcell::app {

// link: the connection's state, null when the master's own bus state holds (a master that is
// not started keeps its last bus state: the link says what holds now).
inline ui::DevicePanelSnapshot toPanelSnapshot(const canopen::CanBusSnapshot& s,
                                               const std::vector<QString>& axisNames,
                                               const CutCell::ui::RigLink* link = nullptr,
                                               double heartbeatTimeoutMs = 0) {
    using namespace cutcell::canopen;
    using LinkState = CutCell::ui::RigLink::State;
    ui::DevicePanelSnapshot p;
    p.can = true;
    p.heartbeat_timeout_ms = heartbeatTimeoutMs;
    if (!link || link->state == LinkState::Up) {
        p.bus_state = QString::fromStdString(s.bus_text.empty() ? toString(s.bus) : s.bus_text);
        p.bus_error = s.bus == BusState::BusOff || s.bus == BusState::Disconnected ||
                      s.bus == BusState::ErrorPassive;
    } else {
        p.bus_state = QString::fromLatin1(toString(link->state)) + QStringLiteral(": ") +
                      QString::fromStdString(link->text);
        p.bus_error = link->state == LinkState::Lost || link->state == LinkState::Failed;
    }
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
