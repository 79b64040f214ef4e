#pragma once
// A CiA 402 drive holds its position (0x607A target, 0x6064 actual) in a signed 32-bit count.
// The job's validation keeps every axis with a travel inside it; a continuous axis (the saw's
// turntable, the quick-return crank) turns on without end, so its bound comes from the run:
// the farthest the program takes it. Checked before a program runs on CAN drives.
#include "core/common/outcome.h"
#include "core/engine/motion_program.h"
#include "core/job/job.h"

namespace cutcell {

// The farthest |position| (rad or mm) the program takes axis i in one run: the spline's knots
// and the start for a spline program; endless_reach, else the travel limits, for a source.
double programReach(const MotionProgram& program, int axis);

// Every axis's reach times its devices.counts_per_unit within 2^31 - 1 counts; else Refused,
// naming the key, the axis, the reach, the counts and the largest counts_per_unit that fits.
Outcome countsFitProgram(const Job& job, const MotionProgram& program);

} // namespace cutcell
