#pragma once
// Speed figures of the section-steel cutter for `cutcell-cli bench` (printed, never asserted).
#include "core/json/json.h"

namespace cutcell::section_steel {

// section_ik_ns_per_solve (5-DOF full pose, closed form, all branches),
// section_torch_ik_ns_per_solve (5-DOF torch tip + direction, root search, all branches),
// section_end_cut_plan_ms (the default job's full end cut: path, IK per point, spline).
void benchSectionSteel(bool quick, json::Object& out);

} // namespace cutcell::section_steel
