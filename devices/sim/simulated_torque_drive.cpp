#include "devices/sim/simulated_torque_drive.h"

namespace cutcell {

SimulatedTorqueDrive::SimulatedTorqueDrive(const SimulatedTorqueDriveConfig& config)
    : cfg_(config) {
    plant_.configure(cfg_.plant, cfg_.period_s);
    plant_.setState(cfg_.initial_position, 0);
}

void SimulatedTorqueDrive::activate() {
    if (state_ != DriveState::Disabled) return;
    state_ = DriveState::Enabling;
    stateSince_ = -1;
}

void SimulatedTorqueDrive::deactivate() {
    if (state_ == DriveState::Fault) return;
    state_ = DriveState::Disabled;
    stateSince_ = -1;
}

void SimulatedTorqueDrive::quickStop() {
    deactivate();
}

void SimulatedTorqueDrive::faultReset() {
    if (state_ != DriveState::Fault) return;
    injectedFault_.store(0);
    faultCode_ = 0;
    state_ = DriveState::Disabled;
    stateSince_ = -1;
}

DriveFeedback SimulatedTorqueDrive::read(double now_s) {
    if (stateSince_ < 0) stateSince_ = now_s;
    const std::uint32_t injected = injectedFault_.load(std::memory_order_relaxed);
    if (injected != 0 && state_ != DriveState::Fault) {
        state_ = DriveState::Fault;
        faultCode_ = injected;
        stateSince_ = now_s;
    }
    if (state_ == DriveState::Enabling &&
        now_s - stateSince_ + 0.5 * cfg_.period_s >= cfg_.enable_delay_s) {
        state_ = DriveState::Enabled;
        stateSince_ = now_s;
    }
    DriveFeedback fb;
    fb.position = plant_.position();
    fb.velocity = plant_.velocity();
    fb.state = state_;
    fb.fault_code = faultCode_;
    fb.torque_ratio = plant_.torqueLimit() > 0 ? applied_ / plant_.torqueLimit() : 0;
    return fb;
}

void SimulatedTorqueDrive::step(double torque) {
    const double motor = state_ == DriveState::Enabled ? torque : 0.0;
    applied_ = plant_.step(motor);
    ++writes_;
}

void SimulatedTorqueDrive::write(double targetPosition) {
    (void)targetPosition;
    step(0);
}

void SimulatedTorqueDrive::writeTorque(double torque) {
    step(torque);
}

} // namespace cutcell
