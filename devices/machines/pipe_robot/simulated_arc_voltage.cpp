#include "devices/machines/pipe_robot/simulated_arc_voltage.h"

namespace cutcell {

SimulatedArcVoltage::SimulatedArcVoltage(
    const PipeRobot& robot, const RobotTorchHeightSetup& setup,
    const std::array<const SimulatedDrive*, kAxisCount>& drives, const SimulatedTorch& torch)
    : robot_(robot), cutHeight_(setup.process.cut_height_mm), surface_(setup.pipe), arc_(setup.arc),
      drives_(drives), torch_(torch) {}

SensorReading SimulatedArcVoltage::read(double) {
    SensorReading r;
    if (!torch_.isOn()) return r; // no arc, no voltage
    ArmVector q;
    for (int i = 0; i < kArmJointCount; ++i)
        q[i] = drives_[static_cast<size_t>(i + 1)]->truePosition();
    const double chuck = drives_[0]->truePosition();
    const Pose tool = robot_.forward(q);
    // The planned tool point lies on the nominal surface; the torch tip stands the cut height
    // above it along the torch axis. The actual surface lies s further along the axis.
    const Vec3 tipOnWork = robot_.workFromBase(chuck, tool.translation());
    const Vec3 axisOnWork = robot_.baseFromWork(chuck).linear().transpose() * tool.linear().col(2);
    const SurfaceHit hit = surface_.alongLine(tipOnWork, axisOnWork);
    if (!hit.ok) return r;
    lastStandoff_ = cutHeight_ + hit.s_mm;
    r.position = arc_.voltage(lastStandoff_);
    r.valid = true;
    return r;
}

} // namespace cutcell
