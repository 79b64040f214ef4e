#include "ui/machine_plan.h"

#include "core/machine/machine_registry.h"
#include "core/machines/pipe_robot/pipe_robot_program.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/profile_cutter_program.h"

#include <cmath>
#include <stdexcept>

namespace CutCell::ui {

bool isProfileCutterJob(const cutcell::Job& job) {
    return job.machine == kProfileCutterMachine;
}

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

std::shared_ptr<const cutcell::MotionProgram> buildMachineProgram(const cutcell::Job& job,
                                                                  const cutcell::CutPlan& plan,
                                                                  const std::string& text) {
    if (isProfileCutterJob(job)) return cutcell::buildProfileCutterProgram(job, text);
    return cutcell::buildPipeRobotProgram(job, plan, text);
}

std::size_t plannedPointCount(const cutcell::Job& job, const cutcell::CutPlan& plan) {
    if (!isProfileCutterJob(job)) return plan.knots.size();
    if (plan.knot_dt_s <= 0) return 0;
    return static_cast<std::size_t>(std::lround(plan.cut_time_s / plan.knot_dt_s));
}

} // namespace CutCell::ui
