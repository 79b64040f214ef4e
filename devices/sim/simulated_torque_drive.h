#pragma once
// A simulated drive in cyclic synchronous torque mode (CiA 402 CST): no inner loop, the plant
// takes the commanded torque (rotary, N m) or force (linear, N) directly, J q'' + b q' =
// sat(u), one step per cycle at the write. While not Enabled no torque is applied (the
// axis coasts). Lifecycle and fault injection as SimulatedDrive.
//
// Threading contract: AxisDrive calls come from the engine thread only; inject*() from any
// thread; the probes (appliedTorque, truePosition) from the engine thread or between cycles.
#include "core/control/joint_plant.h"
#include "core/devices/device_interfaces.h"
#include "devices/sim/linear_position_sensor.h"

#include <atomic>
#include <cstdint>

namespace cutcell {

struct SimulatedTorqueDriveConfig {
    JointPlantParams plant; // inertia (kg m^2 or kg), viscous, torque (force) limit
    double period_s = 0.001;
    double initial_position = 0;
    double enable_delay_s = 0.002;
};

class SimulatedTorqueDrive : public AxisDrive, public TruePositionProbe {
  public:
    explicit SimulatedTorqueDrive(const SimulatedTorqueDriveConfig& config);

    void activate() override;
    void deactivate() override;
    void quickStop() override; // no position loop to hold with: torque off at once
    void faultReset() override;
    DriveFeedback read(double now_s) override;
    void write(double targetPosition) override; // not in CST: steps the plant without torque
    bool setCommandMode(AxisCommandMode mode) override { return mode == AxisCommandMode::Torque; }
    AxisCommandMode commandMode() const override { return AxisCommandMode::Torque; }
    void writeTorque(double torque) override;

    void injectFault(std::uint32_t code) { injectedFault_.store(code); }

    double appliedTorque() const { return applied_; } // of the last write
    std::uint64_t writes() const { return writes_; }
    double truePosition() const override { return plant_.position(); }
    double trueVelocity() const override { return plant_.velocity(); }

  private:
    void step(double torque);
    SimulatedTorqueDriveConfig cfg_;
    JointPlant plant_;
    DriveState state_ = DriveState::Disabled;
    std::uint32_t faultCode_ = 0;
    double stateSince_ = -1;
    double applied_ = 0;
    std::uint64_t writes_ = 0;
    std::atomic<std::uint32_t> injectedFault_{0};
};

} // namespace cutcell
