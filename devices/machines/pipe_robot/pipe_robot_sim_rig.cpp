// The pipe robot's simulated cell: six simulated drives (the job's PID) sharing the job's
// mechanics (pipe_robot_shared_mechanics.h: the plant simulateCut() runs), and a simulated torch.
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "devices/machines/pipe_robot/pipe_robot_shared_mechanics.h"
#include "devices/machines/pipe_robot/simulated_arc_voltage.h"
#include "devices/machines/sim_rigs.h"
#include "devices/sim/simulated_drive.h"
#include "devices/sim/simulated_torch.h"

#include <array>

namespace cutcell {
namespace {

class PipeRobotSimRig : public MachineSimRig {
  public:
    PipeRobotSimRig(const Job& job, const MotionProgram& program) : job_(job) {
        const PipeRobotSpec& spec = pipeRobotSpec(job);
        const auto mechanics =
            makePipeRobotSharedMechanics(job, job.sim.period_s, program.reference);
        for (size_t i = 0; i < drives_.size(); ++i) {
            SimulatedDriveConfig dc;
            dc.gains = spec.controller[i];
            dc.plant = spec.plant[i];
            dc.period_s = job.sim.period_s;
            dc.initial_position = program.reference[static_cast<int>(i)];
            dc.mechanics = mechanics;
            dc.axis = static_cast<int>(i);
            drives_[i] = std::make_unique<SimulatedDrive>(dc);
        }
        // The torch height control reads the arc voltage: the simulated arc over the job's
        // actual pipe (process.torch_height.simulated_pipe).
        if (const RobotTorchHeightSetup thc = robotTorchHeightSetup(job);
            thc.used && thc.problem.empty()) {
            std::array<const SimulatedDrive*, kAxisCount> d{};
            for (size_t i = 0; i < drives_.size(); ++i)
                d[i] = drives_[i].get();
            arc_ = std::make_unique<SimulatedArcVoltage>(PipeRobot(spec.dh), thc, d, torch_);
        }
    }
    EngineDevices devices() override {
        EngineDevices d;
        for (size_t i = 0; i < drives_.size(); ++i)
            d.axes[i] = drives_[i].get();
        d.torch = &torch_;
        d.sensors[static_cast<size_t>(kArcVoltageSensor)] = arc_.get();
        return d;
    }
    void configure(EngineConfig& config) const override {
        config.period_s = job_.sim.period_s;
        config.in_position_window = pipeRobotInPositionWindow(job_, config.in_position_window);
    }
    std::string description() const override {
        return arc_ ? "Simulated cell: 6 drives + torch + arc voltage (out-of-round pipe)"
                    : "Simulated cell: 6 drives + torch";
    }

  private:
    Job job_;
    std::array<std::unique_ptr<SimulatedDrive>, kAxisCount> drives_;
    SimulatedTorch torch_;
    std::unique_ptr<SimulatedArcVoltage> arc_;
};

} // namespace

std::unique_ptr<MachineSimRig> makePipeRobotSimRig(const Job& job, const MotionProgram& program) {
    return std::make_unique<PipeRobotSimRig>(job, program);
}

} // namespace cutcell
