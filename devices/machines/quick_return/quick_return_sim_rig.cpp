#include "devices/machines/quick_return/quick_return_sim_rig.h"

#include "core/machines/quick_return/quick_return_module.h"
#include "devices/machines/sim_rigs.h"

#include <cmath>
#include <numbers>

namespace cutcell {

QuickReturnCrankDrive::QuickReturnCrankDrive(const quick_return::ExperimentSetup& s, double q0)
    : s_(s), plant_(s.law.dims, s.plant) {
    plant_.setState(q0, 0);
}

void QuickReturnCrankDrive::activate() {
    if (state_ == DriveState::Disabled) {
        state_ = DriveState::Enabling;
        since_ = -1;
    }
}

void QuickReturnCrankDrive::deactivate() {
    state_ = DriveState::Disabled;
    since_ = -1;
}

DriveFeedback QuickReturnCrankDrive::read(double now_s) {
    if (since_ < 0) since_ = now_s;
    if (state_ == DriveState::Enabling && now_s - since_ + 0.5 * s_.sample_time >= 0.002)
        state_ = DriveState::Enabled;
    DriveFeedback fb;
    fb.position = plant_.state().q;
    fb.velocity = plant_.state().dq;
    fb.state = state_;
    fb.torque_ratio = applied_ / s_.plant.torque_limit;
    return fb;
}

void QuickReturnCrankDrive::step(double torque) {
    const double t = static_cast<double>(writes_) * s_.sample_time;
    const double dist =
        s_.disturbance_amplitude * std::sin(2 * std::numbers::pi * s_.disturbance_hz * t);
    const bool on = state_ == DriveState::Enabled;
    // Torque off: the motor gives none, and no disturbance is injected through it either.
    applied_ =
        on ? plant_.step(torque, dist, s_.sample_time) : (plant_.step(0, 0, s_.sample_time), 0.0);
    ++writes_;
}

QuickReturnSimRig::QuickReturnSimRig(const quick_return::ExperimentSetup& s,
                                     const MotionProgram& program)
    : period_(s.sample_time), drive_(s, program.start_position[0]), probe_(drive_),
      sensor_(probe_, 1000 * s.scale_resolution) {}

EngineDevices QuickReturnSimRig::devices() {
    EngineDevices d;
    d.axes[0] = &drive_;
    d.sensors[0] = &sensor_;
    return d;
}

void QuickReturnSimRig::configure(EngineConfig& config) const {
    config.period_s = period_;
    config.in_position_window = 0.01; // rad: a crank held by a PD against the slider's weight
    config.in_position_velocity = 0.05;
    config.frozen_feedback_travel = 0.05;
}

std::unique_ptr<MachineSimRig> makeQuickReturnSimRig(const Job& job, const MotionProgram& program) {
    (void)job;
    const auto* law = dynamic_cast<const quick_return::QuickReturnLaw*>(program.source.get());
    if (!law) throw std::invalid_argument("the program has no quick-return control law");
    quick_return::ExperimentSetup s;
    if (const Outcome set = buildSetup(quickReturnSpec(job), &s); !set.ok())
        throw std::invalid_argument(set.message);
    s.plant.contact = law->config().experiment == quick_return::Experiment::Cutting;
    return std::make_unique<QuickReturnSimRig>(s, program);
}

} // namespace cutcell
