#pragma once
// CSV exports of a plan: path.csv (the cut point in the main pipe frame, then the torch pose
// in the robot base frame) and joints.csv (time and all joint angles at the control period).
#include "core/job/job.h"
#include "core/machines/pipe_robot/cut_planner.h"

#include <string>

namespace cutcell {

std::string pathCsv(const CutPlan& plan);
std::string jointsCsv(const CutPlan& plan, double period_s);

} // namespace cutcell
