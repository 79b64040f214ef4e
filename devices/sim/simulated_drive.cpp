#include "devices/sim/simulated_drive.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

SimulatedDrive::SimulatedDrive(const SimulatedDriveConfig& config)
    : cfg_(config), mech_(config.mechanics.get()), axis_(config.axis) {
    pid_.configure(cfg_.gains, cfg_.period_s);
    plant_.configure(cfg_.plant, cfg_.period_s);
    plant_.setState(cfg_.initial_position, 0);
    sensed_ = mech_ ? mech_->position(axis_) : cfg_.initial_position;
    updateBrake();
}

void SimulatedDrive::updateBrake() {
    if (mech_)
        mech_->setHeld(axis_, state_ != DriveState::Enabled && state_ != DriveState::QuickStop);
}

void SimulatedDrive::activate() {
    if (state_ != DriveState::Disabled) return;
    state_ = DriveState::Enabling;
    stateSince_ = -1;
    updateBrake();
}

void SimulatedDrive::deactivate() {
    if (state_ == DriveState::Fault) return;
    state_ = DriveState::Disabled;
    stateSince_ = -1;
    updateBrake();
}

void SimulatedDrive::quickStop() {
    if (state_ != DriveState::Enabled && state_ != DriveState::Enabling) return;
    // From Enabling the axis was on its brake: the loop takes over with the holding torque.
    if (mech_ && state_ == DriveState::Enabling) pid_.preload(mech_->preloadTorque(axis_));
    state_ = DriveState::QuickStop;
    holdPosition_ = sensed_;
    stateSince_ = -1;
    updateBrake();
}

void SimulatedDrive::faultReset() {
    if (state_ != DriveState::Fault) return;
    injectedFault_.store(0);
    faultCode_ = 0;
    state_ = DriveState::Disabled;
    stateSince_ = -1;
    updateBrake();
}

void SimulatedDrive::clearInjections() {
    injectedFault_.store(0);
    loadTorque_.store(0);
    frozen_.store(false);
    stale_.store(false);
}

DriveFeedback SimulatedDrive::read(double now_s) {
    now_ = now_s;
    // The cell's first read of a cycle steps the mechanics with the torques of the last one.
    if (mech_) mech_->update();
    if (stateSince_ < 0) stateSince_ = now_s;
    const std::uint32_t injected = injectedFault_.load(std::memory_order_relaxed);
    if (injected != 0 && state_ != DriveState::Fault) {
        state_ = DriveState::Fault;
        faultCode_ = injected;
        stateSince_ = now_s;
        updateBrake();
    }
    // Half a period of margin so a delay of k periods takes exactly k cycles.
    const double margin = 0.5 * cfg_.period_s;
    if (state_ == DriveState::Enabling && now_s - stateSince_ + margin >= cfg_.enable_delay_s) {
        state_ = DriveState::Enabled;
        stateSince_ = now_s;
        holdPosition_ = sensed_;
        if (mech_) {
            // Taking over from the brake: the loop starts with the torque that holds the axis.
            updateBrake();
            pid_.preload(mech_->preloadTorque(axis_));
        } else {
            pid_.reset();
        }
    }
    if (state_ == DriveState::QuickStop && now_s - stateSince_ + margin >= cfg_.quick_stop_s) {
        state_ = DriveState::Disabled;
        stateSince_ = now_s;
        updateBrake();
    }
    const bool frozen = frozen_.load(std::memory_order_relaxed);
    if (!frozen) sensed_ = truePosition();
    wasFrozen_ = frozen;
    if (mech_) {
        const double lim = mech_->torqueLimit(axis_);
        torqueRatio_ = lim > 0 ? mech_->applied(axis_) / lim : 0;
    }
    DriveFeedback fb;
    fb.position = sensed_;
    fb.velocity = frozen ? 0.0 : trueVelocity();
    fb.state = state_;
    fb.fault_code = faultCode_;
    fb.feedback_valid = !stale_.load(std::memory_order_relaxed);
    fb.torque_ratio = torqueRatio_;
    return fb;
}

void SimulatedDrive::write(double targetPosition) {
    // The loop closes on what the encoder says (sampled at read()), like a real drive.
    double command = 0;
    if (state_ == DriveState::Enabled)
        command = pid_.step(targetPosition - sensed_);
    else if (state_ == DriveState::QuickStop)
        command = pid_.step(holdPosition_ - sensed_);
    else
        pid_.reset();
    const double load = loadTorque_.load(std::memory_order_relaxed);
    if (mech_) {
        // The hub adds the feed-forward and the load, and steps at the next cycle's first read.
        mech_->command(axis_, command, load, sensed_);
        return;
    }
    // An external load (collision, overload) adds to the motor torque; the total stays within
    // what the plant model allows.
    if (load != 0) {
        const double lim = plant_.torqueLimit();
        command = std::clamp(command, -lim, lim) + load;
    }
    const double u = plant_.step(command);
    torqueRatio_ = plant_.torqueLimit() > 0 ? u / plant_.torqueLimit() : 0;
}

} // namespace cutcell
