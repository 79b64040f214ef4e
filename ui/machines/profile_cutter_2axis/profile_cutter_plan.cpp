#include "ui/machines/profile_cutter_2axis/profile_cutter_plan.h"

#include "core/machine/machine_registry.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/profile_cutter_program.h"

#include <cmath>

namespace CutCell::ui {

cutcell::CutPlan planProfileCutter(const cutcell::Job& job) {
    cutcell::CutPlan plan;
    plan.method = job.method;
    try {
        // The module's plan: the same feasibility checks (travel, pulse rates) as the CLI.
        const cutcell::MachinePlan mp = cutcell::machineFor(job).plan(job, {});
        if (!mp.ok()) {
            plan.problem = mp.problem;
            return plan; // reachable stays false
        }
        const auto& program = mp.program;
        plan.length_mm = program->length_mm;
        plan.cut_time_s = program->cut_time_s;
        plan.knot_dt_s =
            program->point_count > 0 ? program->cut_time_s / double(program->point_count) : 0;
        plan.reachable = true;
    } catch (const std::exception& e) {
        plan.problem = e.what();
    }
    return plan;
}

std::size_t profileCutterPointCount(const cutcell::CutPlan& plan) {
    if (plan.knot_dt_s <= 0) return 0;
    return static_cast<std::size_t>(std::lround(plan.cut_time_s / plan.knot_dt_s));
}

} // namespace CutCell::ui
