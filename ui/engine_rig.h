#pragma once
// The machine the GUI drives: a motion engine with its devices, built by the composition root
// (app/gui) for a job, so the ui never includes a device header. Destroying a rig stops the
// engine thread and releases the devices.
#include "core/engine/engine_types.h"
#include "core/engine/motion_engine.h"
#include "core/job/job.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cutcell::ui {
struct DevicePanelSnapshot;
}

namespace CutCell::ui {

// The link between a rig's engine and its drives (a fieldbus), for rigs that have one. Plain
// data: the ui knows no transport.
struct RigLink {
    enum class State : std::uint8_t {
        None,       // no link to bring up (in-process drives): always ready
        Down,       // not connected (nothing tried yet, or taken down)
        Connecting, // connecting, configuring the nodes (nodes_ready of nodes so far)
        Up,         // every node operational
        Lost,       // was up; the bus went away (cable, bus off, the bus host ended)
        Failed,     // the last attempt failed (text: what and where); the port is released
    };
    State state = State::None;
    std::string text;          // a sentence: what is happening, or what failed
    std::string where;         // e.g. "virtualcan can0"
    int nodes_ready = 0;       // nodes configured and operational
    int nodes = 0;             // nodes on the link
    std::uint64_t changes = 0; // +1 at every change of the fields above
};

inline const char* toString(RigLink::State s) {
    switch (s) {
    case RigLink::State::None:
        return "none";
    case RigLink::State::Down:
        return "down";
    case RigLink::State::Connecting:
        return "connecting";
    case RigLink::State::Up:
        return "up";
    case RigLink::State::Lost:
        return "lost";
    case RigLink::State::Failed:
        return "failed";
    }
    return "?";
}

struct RigLinkEvent {
    bool error = false;
    std::string text; // e.g. "node 3: heartbeat lost (none for 312 ms > 300 ms)"
};

class EngineRig {
  public:
    virtual ~EngineRig() = default;
    virtual cutcell::MotionEngine& engine() = 0;
    // One line for the status bar, e.g. "simulated cell, 1 ms cycle, real time".
    virtual std::string description() const = 0;
    // The drives and bus for the device panel (GUI thread, never waits on the bus); false:
    // nothing to show beyond "simulated in-process drives".
    virtual bool deviceSnapshot(cutcell::ui::DevicePanelSnapshot& /*out*/) { return false; }
    // The operator's fault reset at the device panel (node 0: every node and the bus).
    virtual void faultReset(int /*node*/) {}

    // The drives' link (GUI thread, never waits). Rigs without one report State::None and
    // ignore the requests below.
    virtual RigLink link() const { return {}; }
    // Brings the link up off the calling thread; progress and outcome show in link(). A no-op
    // while it is up or coming up.
    virtual void connectLink() {}
    // Takes the link down (the drives disabled, the port released) and brings it up again.
    virtual void reconnectLink() {}
    // What happened on the link since the last call (node configured, heartbeat lost, EMCY...).
    virtual std::vector<RigLinkEvent> drainLinkEvents() { return {}; }
};

// Builds a rig (engine thread started) for a job; returns null with *error set on failure.
using EngineRigFactory = std::function<std::unique_ptr<EngineRig>(
    const cutcell::Job& job, cutcell::ClockMode clock, std::string* error)>;

} // namespace CutCell::ui
