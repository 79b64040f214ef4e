#pragma once
// The profile cutter's own part of a job (its struct in Job::machine_spec, see
// core/job/machine_spec.h): the stepper output and the other branch pipes at the joint. The pipe
// joint it cuts (main_pipe, branch_pipe, angle_deg, eccentricity_mm, cut) is shared with the
// pipe robot and read by core/machine/pipe_joint_section.h.
#include "core/job/job.h"
#include "core/job/machine_spec.h"
#include "core/pipe_joint/pipe_joint_extras.h"

#include <vector>

namespace cutcell {

// The 2-axis NC pipe profile cutter of seed 002: torch on a linear X axis over the rotating
// pipe (A axis), both driven by stepper motors through a pulse card.
struct ProfileCutterSpec : MachineSpecOf<ProfileCutterSpec> {
    int steps_per_rev_a = 400;         // the seed's n: interpolation steps per pipe revolution
    int pulses_per_step_a = 16;        // A-axis pulses per step (pulses/rev = n * this)
    double mm_per_pulse_x = 0.005;     // X-axis travel per pulse
    double max_pulse_rate_hz = 200000; // pulse card limit per axis (PCL-839+: 1 Hz .. 200 kHz)
    double pierce_s = 1.0;             // dwell after torch on, before moving
    double x_travel_mm = 3000;         // X carriage travel from 0 (the fixed end) to here
    // Hole cut: X of the branch axis crossing (the seed's S); absent = middle of the main pipe.
    bool branch_position_auto = true;
    double branch_position_mm = 0;
    std::vector<OtherBranch> other_branches; // cut = "branch" only
};

// The profile cutter's section of a job. A job that holds no section yet (one being built in
// code, Job{}) reads as the default one, and the non-const form gives it that one to edit; a job
// holding another machine's section throws std::invalid_argument.
const ProfileCutterSpec& profileCutterSpec(const Job& job);
ProfileCutterSpec& profileCutterSpec(Job& job);
// The cutting templates and the developed cut are drawn for any pipe-joint job (the pipe
// robot's too): a job without the profile cutter's section gives the defaults (no other
// branches, the hole in the middle of the main pipe).
const ProfileCutterSpec& profileCutterSpecOrDefault(const Job& job);
// The joint as the developed cut and the templates need it: the other branches and the hole's
// position (the defaults for a job without the profile cutter's section).
JointExtras jointExtrasOf(const Job& job);

} // namespace cutcell
