#include "ui/machine/module_planned_machine_ui.h"

#include "core/machine/machine_module.h"
#include "core/machine/machine_registry.h"
#include "ui/panels/engine_text.h"

#include <stdexcept>

namespace CutCell::ui {

namespace {
const cutcell::MachinePlan& modulePlan(const cutcell::CutPlan& plan) {
    if (!plan.machine_plan) throw std::invalid_argument("the plan holds no machine module plan");
    return *plan.machine_plan;
}
} // namespace

const cutcell::MachineModule& ModulePlannedMachineUi::module() const {
    const cutcell::MachineModule* m = cutcell::findMachine(id());
    if (!m) throw std::logic_error("no core machine module \"" + id() + "\" is registered");
    return *m;
}

cutcell::Job ModulePlannedMachineUi::defaultJob() const {
    return module().defaultJob();
}

cutcell::CutPlan ModulePlannedMachineUi::plan(const cutcell::Job& job,
                                              const cutcell::PlanOptions&) const {
    cutcell::CutPlan out;
    auto mp = std::make_shared<cutcell::MachinePlan>(module().plan(job, {}));
    out.reachable = mp->ok() && mp->program;
    if (out.reachable) { // the figures every machine's plan has, for the log and the progress
        out.length_mm = mp->program->length_mm;
        out.cut_time_s = mp->program->cut_time_s;
        out.knot_dt_s = mp->program->point_count > 0
                            ? mp->program->cut_time_s / double(mp->program->point_count)
                            : 0;
    }
    out.problem =
        mp->ok() ? (mp->program ? "" : "the machine module gave no program") : mp->problem;
    out.machine_plan = std::move(mp);
    return out;
}

std::shared_ptr<const cutcell::MotionProgram>
ModulePlannedMachineUi::buildProgram(const cutcell::Job&, const cutcell::CutPlan& plan,
                                     const std::string& jobText) const {
    const cutcell::MachinePlan& mp = modulePlan(plan);
    if (!mp.ok() || !mp.program) throw std::invalid_argument(mp.problem);
    // The plan was made without the job's text (off the GUI thread, before saving): the run
    // log's copy of the program carries it.
    auto program = std::make_shared<cutcell::MotionProgram>(*mp.program);
    program->source_text = jobText;
    return program;
}

std::size_t ModulePlannedMachineUi::plannedPointCount(const cutcell::Job&,
                                                      const cutcell::CutPlan& plan) const {
    return plan.machine_plan && plan.machine_plan->program ? plan.machine_plan->program->point_count
                                                           : 0;
}

QString ModulePlannedMachineUi::planSummary(const cutcell::Job&,
                                            const cutcell::CutPlan& plan) const {
    // In the GUI's language where core made it from a template (messageC).
    return plan.machine_plan ? engineText(QString::fromStdString(plan.machine_plan->summary))
                             : QString();
}

std::vector<std::pair<std::string, QString>>
ModulePlannedMachineUi::pipeJointFields(const QString& why) {
    std::vector<std::pair<std::string, QString>> out;
    for (const char* pipe : {"main_pipe", "branch_pipe"})
        for (const char* field : {".radius_mm", ".wall_mm", ".length_mm"})
            out.push_back({std::string(pipe) + field, why});
    for (const char* key :
         {"angle_deg", "eccentricity_mm", "cut.target", "cut.bevel_deg", "cut.speed_mm_s",
          "cut.ramp_s", "cut.knot_spacing_mm", "cut.max_direction_deviation_deg",
          "cut.start_phi_auto", "cut.start_phi_deg"})
        out.push_back({key, why});
    return out;
}

} // namespace CutCell::ui
