#pragma once
// The keys of a simulated drive's row (a PID with first-order filter and the joint plant), one
// table each: the pipe robot's controller[] and plant[] rows and the section steel cutter's
// drives[] rows (which hold both) spell them alike.
#include "core/job/job.h"
#include "core/job/row_table.h"

#include <span>

namespace cutcell {

std::span<const RowField<PidGains>> pidGainFields();
std::span<const RowField<JointPlantParams>> jointPlantFields();

} // namespace cutcell
