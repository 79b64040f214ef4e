#pragma once
// The profile cutter's plan summary for the run controller: its own (fast, closed-form) cut
// computation (computeProfileCut / buildProfileCutterProgram) summarised as a CutPlan
// (reachable/problem, length, time, point count) so the run controller, the log and Start's
// blocking reason treat every machine the same way.
//
// Threading contract: pure functions of their arguments; callable from any thread.
#include "core/job/job.h"
#include "core/trajectory/cut_planner.h"

#include <cstddef>

namespace CutCell::ui {

// reachable = the cut fits the X travel and the program builds; otherwise problem holds the
// core's sentence (key, value, limit). knots stay empty (the robot's joint knots do not exist
// on this machine); knot_dt_s = cut_time_s / points.
cutcell::CutPlan planProfileCutter(const cutcell::Job& job);

// Planned point count (the program's points) for progress.
std::size_t profileCutterPointCount(const cutcell::CutPlan& plan);

} // namespace CutCell::ui
