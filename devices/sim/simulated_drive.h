#pragma once
// A simulated servo drive in cyclic synchronous position mode: it closes the position loop
// itself with the core's PID (first-order filter) on the core's joint plant, one step per
// write(), in the same order as simulateCut() (sample, PID, plant).
//
// Shared mechanics (optional, devices/sim/shared_mechanics.h): the drive's axis is one of the
// cell's coupled mechanics instead of its own joint plant. write() then gives the hub its loop
// torque and the first read() of the next cycle (any drive of the cell) steps all axes at once.
// While the drive has no torque (not Enabled nor QuickStop) its axis is on its brake (held);
// on Enabled the brake releases and the loop starts from the holding torque (PidFilter::
// preload), or from 0 with gravity feed-forward. Without shared mechanics: the joint plant.
//
// Lifecycle like a CiA 402 drive: activate() -> Enabling for enable_delay_s -> Enabled
// (holding its actual position); deactivate() -> Disabled at once (torque off, the axis
// coasts); quickStop() -> QuickStop (holds the position where it was) for quick_stop_s, then
// Disabled; a fault -> Fault (torque off) until faultReset().
//
// Fault injection (tests, demonstrations): a drive fault code, an external load torque (a
// collision: the axis is pushed off its path, the following error grows), frozen feedback (the
// encoder value stops changing while the drive keeps reporting valid data), and stale feedback
// (feedback_valid = false).
//
// Threading contract: AxisDrive calls come from the engine thread only. The inject*() calls
// may come from any thread: they set atomics that the drive picks up at its next read().
#include "core/control/joint_plant.h"
#include "core/control/pid_filter.h"
#include "core/devices/device_interfaces.h"
#include "core/job/job.h"
#include "devices/sim/shared_mechanics.h"

#include <atomic>
#include <cstdint>
#include <memory>

namespace cutcell {

struct SimulatedDriveConfig {
    PidGains gains;
    JointPlantParams plant;
    double period_s = 0.001;
    double initial_position = 0;
    double enable_delay_s = 0.002;
    double quick_stop_s = 0.01;
    // The cell's coupled mechanics and this drive's axis in them (null: the joint plant
    // above, from initial_position; with mechanics, plant and initial_position are unused).
    std::shared_ptr<SharedMechanics> mechanics;
    int axis = 0;
};

class SimulatedDrive : public AxisDrive {
  public:
    explicit SimulatedDrive(const SimulatedDriveConfig& config);

    void activate() override;
    void deactivate() override;
    void quickStop() override;
    void faultReset() override;
    DriveFeedback read(double now_s) override;
    void write(double targetPosition) override;

    // Fault injection (any thread).
    void injectFault(std::uint32_t code) { injectedFault_.store(code); }
    // An external torque on the axis (N m): above what the motor can hold, the axis is pushed
    // off its path and the following error grows.
    void injectLoadTorque(double nm) { loadTorque_.store(nm); }
    void injectFrozenFeedback(bool on) { frozen_.store(on); }
    void injectStaleFeedback(bool on) { stale_.store(on); }
    void clearInjections();

    // Simulation only (engine thread or before the engine runs): the true plant state.
    double truePosition() const { return mech_ ? mech_->position(axis_) : plant_.position(); }
    double trueVelocity() const { return mech_ ? mech_->velocity(axis_) : plant_.velocity(); }

  private:
    // The brake follows the state: on while the drive gives no torque.
    void updateBrake();

    SimulatedDriveConfig cfg_;
    PidFilter pid_;
    JointPlant plant_;
    SharedMechanics* mech_ = nullptr; // owned by cfg_.mechanics
    int axis_ = 0;
    DriveState state_ = DriveState::Disabled;
    std::uint32_t faultCode_ = 0;
    double now_ = 0;
    double stateSince_ = -1;  // engine time of the last transition (-1: stamp at next read)
    double holdPosition_ = 0; // QuickStop target
    double sensed_ = 0;       // encoder value the loop closes on (frozen when injected)
    double torqueRatio_ = 0;  // torque applied in the last write / torque limit
    bool wasFrozen_ = false;
    std::atomic<std::uint32_t> injectedFault_{0};
    std::atomic<bool> frozen_{false}, stale_{false};
    std::atomic<double> loadTorque_{0};
};

} // namespace cutcell
