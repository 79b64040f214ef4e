#include "devices/sim/simulated_stepper.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace cutcell {

SimulatedStepper::SimulatedStepper(const SimulatedStepperConfig& config)
    : cfg_(config),
      maxPerCycle_(std::max<std::int64_t>(
          1, static_cast<std::int64_t>(std::floor(config.max_pulse_rate_hz * config.period_s)))),
      count_(std::llround(config.initial_position / config.units_per_pulse)) {}

void SimulatedStepper::activate() {
    if (state_ != DriveState::Disabled) return;
    state_ = DriveState::Enabling;
    stateSince_ = -1;
}

void SimulatedStepper::deactivate() {
    if (state_ == DriveState::Fault) return;
    state_ = DriveState::Disabled;
    stateSince_ = -1;
}

void SimulatedStepper::quickStop() {
    if (state_ != DriveState::Enabled && state_ != DriveState::Enabling) return;
    state_ = DriveState::QuickStop;
    stateSince_ = -1;
}

void SimulatedStepper::faultReset() {
    if (state_ != DriveState::Fault) return;
    state_ = DriveState::Disabled;
    stateSince_ = -1;
}

DriveFeedback SimulatedStepper::read(double now_s) {
    if (stateSince_ < 0) stateSince_ = now_s;
    const double margin = 0.5 * cfg_.period_s; // a delay of k periods takes k cycles
    if (state_ == DriveState::Enabling && now_s - stateSince_ + margin >= cfg_.enable_delay_s) {
        state_ = DriveState::Enabled;
        stateSince_ = now_s;
    }
    if (state_ == DriveState::QuickStop && now_s - stateSince_ + margin >= cfg_.quick_stop_s) {
        state_ = DriveState::Disabled;
        stateSince_ = now_s;
    }
    DriveFeedback fb;
    fb.position = static_cast<double>(count_) * cfg_.units_per_pulse;
    fb.velocity = static_cast<double>(lastStep_) * cfg_.units_per_pulse / cfg_.period_s;
    fb.state = state_;
    return fb;
}

void SimulatedStepper::write(double targetPosition) {
    lastStep_ = 0;
    if (state_ != DriveState::Enabled) return; // no pulses
    const std::int64_t want = std::llround(targetPosition / cfg_.units_per_pulse) - count_;
    const std::int64_t step = std::clamp(want, -maxPerCycle_, maxPerCycle_);
    if (step != want) ++limited_;
    count_ += step;
    sent_ += static_cast<std::uint64_t>(std::llabs(step));
    lastStep_ = step;
}

} // namespace cutcell
