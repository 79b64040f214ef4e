#include "ui/machines/pipe_robot/pipe_robot_ui.h"
#include "ui/shown_number.h"

#include "core/job/default_job.h"
#include "ui/machines/pipe_robot/controller_form.h"
#include "ui/machines/pipe_robot/method_form.h"
#include "ui/machines/pipe_robot/robot_dh_table_form.h"

#include <QObject>

#ifdef CUTCELL_HAVE_VIEW3D
#include "ui/machines/pipe_robot/pipe_robot_scene.h"
#endif

namespace CutCell::ui {

QString PipeRobotUi::title() const {
    return QObject::tr("Pipe-cutting robot: 5-DOF arm + pipe chuck (6 axes)");
}

cutcell::Job PipeRobotUi::defaultJob() const {
    cutcell::Job job = cutcell::defaultJob();
    job.machine = kId;
    return job;
}

std::vector<FormPage> PipeRobotUi::formPages() const {
    return {
        {QObject::tr("Method"), [](JobEditor* e) -> JobForm* { return new MethodForm(e); }},
        {QObject::tr("Robot"), [](JobEditor* e) -> JobForm* { return new RobotDhTableForm(e); }},
        {QObject::tr("Controller"), [](JobEditor* e) -> JobForm* { return new ControllerForm(e); }},
    };
}

std::vector<ExportKind> PipeRobotUi::exports() const {
    return {ExportKind::TemplateSvg, ExportKind::TemplatePdf};
}

namespace {
// The robot module's own plan data (MachinePlan::data is the CutPlan, also when infeasible).
const cutcell::CutPlan* cutPlanOf(const cutcell::MachinePlan& plan) {
    return static_cast<const cutcell::CutPlan*>(plan.data.get());
}
} // namespace

cutcell::MachinePlan PipeRobotUi::plan(const cutcell::Job& job,
                                       const cutcell::PlanOptions& options) const {
    cutcell::MachinePlan p = MachineUi::plan(job, options);
    if (p.outcome.refused())
        if (const cutcell::CutPlan* cut = cutPlanOf(p); cut && !cut->problem.empty())
            p.outcome.message = cut->problem;
    return p;
}

QString PipeRobotUi::planSummary(const cutcell::Job& job, const cutcell::MachinePlan& plan) const {
    const cutcell::CutPlan* cut = cutPlanOf(plan);
    if (!cut) return MachineUi::planSummary(job, plan);
    return QObject::tr("Planned %1 points, %2 mm in %3 s (max. torch tilt %4 deg).")
        .arg(cut->knots.size())
        .arg(shownNumber(cut->length_mm, 1))
        .arg(shownNumber(cut->cut_time_s, 1))
        .arg(shownNumber(cut->max_deviation_deg, 1));
}

bool PipeRobotUi::buildScene(const cutcell::Job& job, const cutcell::MachinePlan& plan,
                             cutcell::view3d::SceneModel* out, QString* why) const {
#ifdef CUTCELL_HAVE_VIEW3D
    const cutcell::CutPlan* cut = cutPlanOf(plan);
    if (!cut) {
        if (why) *why = QString::fromStdString(plan.outcome.message);
        return false;
    }
    *out = cutcell::view3d::buildRobotScene(job, *cut);
    return true;
#else
    (void)job, (void)plan, (void)out;
    if (why) *why = QObject::tr("3D view not built in this configuration.");
    return false;
#endif
}

} // namespace CutCell::ui
