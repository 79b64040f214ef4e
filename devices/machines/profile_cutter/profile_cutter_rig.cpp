#include "devices/machines/profile_cutter/profile_cutter_rig.h"

#include "core/machines/profile_cutter/profile_cutter_spec.h"

#include <algorithm>

namespace cutcell {
namespace {

SimulatedStepperConfig stepperConfig(const Job& job, double unitsPerPulse, double initial) {
    SimulatedStepperConfig c;
    c.units_per_pulse = unitsPerPulse;
    c.max_pulse_rate_hz = profileCutterSpec(job).max_pulse_rate_hz;
    c.period_s = job.sim.period_s;
    c.initial_position = initial;
    return c;
}

double radPerPulseA(const Job& job) {
    return 2 * kPi /
           (static_cast<double>(profileCutterSpec(job).steps_per_rev_a) *
            profileCutterSpec(job).pulses_per_step_a);
}

} // namespace

ProfileCutterRig::ProfileCutterRig(const Job& job, const MotionProgram& program)
    : aCfg_(stepperConfig(job, radPerPulseA(job), program.reference[0])),
      xCfg_(stepperConfig(job, profileCutterSpec(job).mm_per_pulse_x, program.reference[1])),
      a_(aCfg_), x_(xCfg_), period_s_(job.sim.period_s) {}

EngineDevices ProfileCutterRig::devices() {
    EngineDevices d;
    d.axes[0] = &a_;
    d.axes[1] = &x_;
    d.torch = &torch_;
    return d;
}

void ProfileCutterRig::configure(EngineConfig& config) const {
    config.period_s = period_s_;
    // Half a pulse plus rounding: a stepper's count is as close as it can get.
    config.in_position_window =
        0.5 * std::max(aCfg_.units_per_pulse, xCfg_.units_per_pulse) * (1 + 1e-9);
    config.in_position_velocity = 1e-9;
    // The count moves in whole pulses: the set-point may travel up to 1.5 pulses before it does.
    config.frozen_feedback_travel = 3 * std::max(aCfg_.units_per_pulse, xCfg_.units_per_pulse);
}

} // namespace cutcell
