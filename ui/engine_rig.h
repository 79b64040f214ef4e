#pragma once
// The machine the GUI drives: a motion engine with its devices, built by the composition root
// (app/gui) for a job, so the ui never includes a device header. Destroying a rig stops the
// engine thread and releases the devices.
#include "core/engine/engine_types.h"
#include "core/engine/motion_engine.h"
#include "core/job/job.h"

#include <functional>
#include <memory>
#include <string>

namespace cutcell::ui {
struct DevicePanelSnapshot;
}

namespace CutCell::ui {

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
};

// Builds a rig (engine thread started) for a job; returns null with *error set on failure.
using EngineRigFactory = std::function<std::unique_ptr<EngineRig>(
    const cutcell::Job& job, cutcell::ClockMode clock, std::string* error)>;

} // namespace CutCell::ui
