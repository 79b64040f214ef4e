#pragma once
// The 2-axis NC pipe profile cutter of seed 002: the developed cut of its job's joint (core/
// pipe_joint/developed_cut.h) with its own section's other branches, hole position and grid
// (profile_cutter.steps_per_rev_a), and the carriage's travel check.
#include "core/job/job.h"
#include "core/machines/profile_cutter/profile_cutter_spec.h"
#include "core/pipe_joint/developed_cut.h"

#include <string>

namespace cutcell {

// The torch's cut of the job on n grid steps, or on the job's own grid (steps_per_rev_a): the
// part's edge moved by half the kerf of the job's process (profile_kerf.h); the edge itself
// when the job has no kerf. A kerf that cannot be compensated leaves the edge and says why in
// kerf_problem (the plan refuses the job).
ProfileCut computeProfileCut(const Job& job, int n);
ProfileCut computeProfileCut(const Job& job);
// The part's edge (no compensation).
ProfileCut computeProfileEdge(const Job& job, int n);
// The kerf the job's process asks for (0 without a process section or a kerf).
double profileKerfMm(const Job& job);

// Empty when every X of the cut lies on the carriage (0 .. profile_cutter.x_travel_mm); else one
// sentence naming the point, the value and the key.
std::string travelProblem(const Job& job, const ProfileCut& cut);

} // namespace cutcell
