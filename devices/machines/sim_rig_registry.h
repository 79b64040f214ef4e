#pragma once
// The simulated devices of each machine, beside the devices and keyed by the machine module's
// id: the core's MachineModule says what a machine is and plans it; the rig here is its mock
// hardware (as ros2_control keeps a mock and a real hardware interface behind one interface).
// CANopen drives are generic (devices/canopen) and serve every machine whose module says
// canOpen().
//
// Adding a machine's simulated devices: a factory function in this folder and one line in
// sim_rig_registry.cpp.
#include "core/engine/motion_engine.h"
#include "core/engine/motion_program.h"
#include "core/job/job.h"
#include "core/json/json.h"

#include <memory>
#include <string>

namespace cutcell {

class MachineSimRig {
  public:
    virtual ~MachineSimRig() = default;
    // The devices for the engine (they live as long as the rig).
    virtual EngineDevices devices() = 0;
    // Engine settings the machine needs (period, in-position window, gains); the caller sets
    // the clock and the engine spec afterwards.
    virtual void configure(EngineConfig& config) const = 0;
    // Adds the machine's device figures (e.g. pulses sent) to a run report.
    virtual void addToReport(json::Value&) const {}
    // One line after a run ("completed: A 6400 pulses ...").
    virtual std::string summary(const std::string& outcome) const { return outcome; }
    // "Simulated cell: 6 drives + torch".
    virtual std::string description() const = 0;
};

// The simulated rig of job.machine for this program; nullptr and *error when the machine has
// none.
std::unique_ptr<MachineSimRig> makeSimulatedRig(const Job& job, const MotionProgram& program,
                                                std::string* error);

} // namespace cutcell
