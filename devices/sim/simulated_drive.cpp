#include "devices/sim/simulated_drive.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

SimulatedDrive::SimulatedDrive(const SimulatedDriveConfig& config) : cfg_(config) {
    pid_.configure(cfg_.gains, cfg_.period_s);
    plant_.configure(cfg_.plant, cfg_.period_s);
    plant_.setState(cfg_.initial_position, 0);
    sensed_ = cfg_.initial_position;
}

void SimulatedDrive::activate() {
    if (state_ != DriveState::Disabled) return;
    state_ = DriveState::Enabling;
    stateSince_ = -1;
}

void SimulatedDrive::deactivate() {
    if (state_ == DriveState::Fault) return;
    state_ = DriveState::Disabled;
    stateSince_ = -1;
}

void SimulatedDrive::quickStop() {
    if (state_ != DriveState::Enabled && state_ != DriveState::Enabling) return;
    state_ = DriveState::QuickStop;
    holdPosition_ = sensed_;
    stateSince_ = -1;
}

void SimulatedDrive::faultReset() {
    if (state_ != DriveState::Fault) return;
    injectedFault_.store(0);
    faultCode_ = 0;
    state_ = DriveState::Disabled;
    stateSince_ = -1;
}

void SimulatedDrive::clearInjections() {
    injectedFault_.store(0);
    loadTorque_.store(0);
    frozen_.store(false);
    stale_.store(false);
}

DriveFeedback SimulatedDrive::read(double now_s) {
    now_ = now_s;
    if (stateSince_ < 0) stateSince_ = now_s;
    const std::uint32_t injected = injectedFault_.load(std::memory_order_relaxed);
    if (injected != 0 && state_ != DriveState::Fault) {
        state_ = DriveState::Fault;
        faultCode_ = injected;
        stateSince_ = now_s;
    }
    // Half a period of margin so a delay of k periods takes exactly k cycles.
    const double margin = 0.5 * cfg_.period_s;
    if (state_ == DriveState::Enabling && now_s - stateSince_ + margin >= cfg_.enable_delay_s) {
        state_ = DriveState::Enabled;
        stateSince_ = now_s;
        holdPosition_ = sensed_;
        pid_.reset();
    }
    if (state_ == DriveState::QuickStop && now_s - stateSince_ + margin >= cfg_.quick_stop_s) {
        state_ = DriveState::Disabled;
        stateSince_ = now_s;
    }
    const bool frozen = frozen_.load(std::memory_order_relaxed);
    if (!frozen) sensed_ = plant_.position();
    wasFrozen_ = frozen;
    DriveFeedback fb;
    fb.position = sensed_;
    fb.velocity = frozen ? 0.0 : plant_.velocity();
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
    // An external load (collision, overload) adds to the motor torque; the total stays within
    // what the plant model allows.
    const double load = loadTorque_.load(std::memory_order_relaxed);
    if (load != 0) {
        const double lim = plant_.torqueLimit();
        command = std::clamp(command, -lim, lim) + load;
    }
    const double u = plant_.step(command);
    torqueRatio_ = plant_.torqueLimit() > 0 ? u / plant_.torqueLimit() : 0;
}

} // namespace cutcell
