#pragma once
// path.csv of the profile cutter (the robot's is core/machines/pipe_robot/plan_csv.h): one row per
// point of the seed's grid and a last row that closes the cut, with the time and developed length
// at the point, the cut point in the main pipe frame, the X/A axis targets, the pipe that sets the
// point (0 = main, k = other branch k), the absolute pulse positions and the pulse counts and
// rates of the step that leaves the point (the seed's N' as the card sees it).
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/stepper_schedule.h"

#include <string>

namespace cutcell {

std::string profilePathCsv(const ProfileCut& cut, const PulseSchedule& schedule);

} // namespace cutcell
