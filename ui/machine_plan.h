#pragma once
// Which machine a job drives, and the per-machine planning and program building the run
// controller needs. The robot plans with planCut; the 2-axis profile cutter (seed 002) has its
// own cut computation (computeProfileCut / buildProfileCutterProgram), summarised here as a
// CutPlan (reachable/problem, length, time, point count) so the run controller, the log and
// Start's blocking reason treat both machines the same way.
//
// Threading contract: pure functions of their arguments; callable from any thread.
#include "core/engine/motion_program.h"
#include "core/job/job.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"
#include "core/trajectory/cut_planner.h"

#include <memory>
#include <string>

namespace CutCell::ui {

inline constexpr const char* kProfileCutterMachine = cutcell::kProfileCutterId;

bool isProfileCutterJob(const cutcell::Job& job);

// The profile cutter's plan summary: reachable = the cut fits the X travel and the program
// builds; otherwise problem holds the core's sentence (key, value, limit). knots stay empty
// (the robot's joint knots do not exist on this machine); knot_dt_s = cut_time_s / points.
cutcell::CutPlan planProfileCutter(const cutcell::Job& job);

// The motion program of the job's machine (throws std::invalid_argument with the core's
// message when the job cannot be run).
std::shared_ptr<const cutcell::MotionProgram>
buildMachineProgram(const cutcell::Job& job, const cutcell::CutPlan& plan, const std::string& text);

// Planned point count for progress: the plan's knots (robot) or the program's points (profile).
std::size_t plannedPointCount(const cutcell::Job& job, const cutcell::CutPlan& plan);

} // namespace CutCell::ui
