#pragma once
// path.csv of the profile cutter (the robot's is core/machines/pipe_robot/plan_csv.h): one row per
// point of the seed's grid and a last row that closes the cut, with the time and developed length
// at the point, the cut point in the main pipe frame, the X/A axis targets, the pipe that sets the
// point (0 = main, k = other branch k), the absolute pulse positions and the pulse counts and
// rates of the step that leaves the point (the seed's N' as the card sees it).
//
// With leads (profile_lead.h) the rows follow the torch from the pierce point: the lead-in rows,
// the cut's rows, the lead-out rows (overlap past the start, then the lead), one index, time and
// length from the pierce point, and a last column "part" = lead_in, cut or lead_out. A lead row
// leaves beta_deg, x_mm, y_mm, z_mm and pipe empty (a lead point is not on the joint's edge);
// its pulses are rounded from its absolute X/A as the cut's, its step runs at the cutting speed
// as the G-code's. Without leads the file is the cut's alone, as before (no "part" column).
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/profile_lead.h"
#include "core/machines/profile_cutter/stepper_schedule.h"

#include <string>

namespace cutcell {

std::string profilePathCsv(const ProfileCut& cut, const PulseSchedule& schedule);
std::string profilePathCsv(const ProfileCut& cut, const PulseSchedule& schedule,
                           const ProfileLeads& leads, double speed_mm_s);

} // namespace cutcell
