#pragma once
// The simulated cell's arc voltage (issue 24): the torch's standoff above the actual pipe (an
// out-of-round pipe mounted off-centre, core/process/pipe_surface.h) from the drives' true
// positions, turned into a voltage by the arc model (core/process/torch_height.h). Valid while
// the torch is lit; read on the engine thread (no allocation, lock or wait).
#include "core/machines/pipe_robot/pipe_robot.h"
#include "core/machines/pipe_robot/robot_torch_height.h"
#include "devices/sim/simulated_drive.h"
#include "devices/sim/simulated_torch.h"

#include <array>

namespace cutcell {

class SimulatedArcVoltage : public SensorInput {
  public:
    SimulatedArcVoltage(const PipeRobot& robot, const RobotTorchHeightSetup& setup,
                        const std::array<const SimulatedDrive*, kAxisCount>& drives,
                        const SimulatedTorch& torch);
    SensorReading read(double now_s) override;
    // The true standoff of the last read (mm), for tests: what the voltage stands for.
    double lastStandoff() const { return lastStandoff_; }

  private:
    PipeRobot robot_;
    double cutHeight_;
    ActualPipeSurface surface_;
    ArcModel arc_;
    std::array<const SimulatedDrive*, kAxisCount> drives_;
    const SimulatedTorch& torch_;
    double lastStandoff_ = 0;
};

} // namespace cutcell
