#pragma once
// Stepper output of the profile cutter (seed 002): the cut's X and A positions become pulse
// counts per interpolation step, and each step gets a duration so that the torch moves over the
// pipe surface at the cutting speed (the seed's reason: an oxy-fuel cut fails when the rate
// varies). The step's surface distance is measured on the quantised positions the motors
// really reach: ds = sqrt((dpx * mm_per_pulse)^2 + (R_w * dpa * rad_per_pulse)^2), dt = ds / v,
// and each axis's pulse rate over the step is |dp| / dt.
//
// Positions are rounded once, from the absolute target (p_i = round(X_i / mm_per_pulse)), so the
// rounding never accumulates: the pulse counts of steps 0..k sum exactly to p_{k+1} - p_0, and
// over the closed cut to zero (X) or to one revolution (A, branch end).
#include "core/job/job.h"
#include "core/machines/profile_cutter/profile_cutter.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cutcell {

struct PulseStep {
    std::int64_t x_pulses = 0; // signed: direction + count for the card
    std::int64_t a_pulses = 0;
    double ds_mm = 0;     // surface distance of the step
    double dt_s = 0;      // duration at the cutting speed
    double x_rate_hz = 0; // pulse rates over the step
    double a_rate_hz = 0;
};

struct PulseSchedule {
    double mm_per_pulse_x = 0;
    double deg_per_pulse_a = 0;
    std::int64_t x_start_pulses = 0; // absolute position of the first point
    std::int64_t a_start_pulses = 0;
    std::vector<PulseStep> steps; // one per grid step, the closing step included
    double total_time_s = 0;
    double developed_length_mm = 0; // sum of ds
    double max_x_rate_hz = 0;
    double max_a_rate_hz = 0;
    // Empty when every rate is within max_pulse_rate_hz; else one sentence naming the step.
    std::string problem;
};

PulseSchedule buildPulseSchedule(const ProfileCut& cut, const ProfileCutterSpec& spec,
                                 double speed_mm_s);

} // namespace cutcell
