#include "ui/machines/pipe_robot/pipe_robot_ui.h"
#include "ui/shown_number.h"

#include "core/job/default_job.h"
#include "core/machines/pipe_robot/pipe_robot_program.h"
#include "ui/machines/pipe_robot/controller_form.h"
#include "ui/machines/pipe_robot/method_form.h"
#include "ui/machines/pipe_robot/robot_dh_table_form.h"

#include <QObject>

#ifdef CUTCELL_HAVE_VIEW3D
#include "ui/view3d/scene_model.h"
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

cutcell::CutPlan PipeRobotUi::plan(const cutcell::Job& job,
                                   const cutcell::PlanOptions& options) const {
    return cutcell::planCut(job, options);
}

std::shared_ptr<const cutcell::MotionProgram>
PipeRobotUi::buildProgram(const cutcell::Job& job, const cutcell::CutPlan& plan,
                          const std::string& jobText) const {
    return cutcell::buildPipeRobotProgram(job, plan, jobText);
}

std::size_t PipeRobotUi::plannedPointCount(const cutcell::Job&,
                                           const cutcell::CutPlan& plan) const {
    return plan.knots.size();
}

QString PipeRobotUi::planSummary(const cutcell::Job&, const cutcell::CutPlan& plan) const {
    return QObject::tr("Planned %1 points, %2 mm in %3 s (max. torch tilt %4 deg).")
        .arg(plan.knots.size())
        .arg(shownNumber(plan.length_mm, 1))
        .arg(shownNumber(plan.cut_time_s, 1))
        .arg(shownNumber(plan.max_deviation_deg, 1));
}

bool PipeRobotUi::buildScene(const cutcell::Job& job, const cutcell::CutPlan& plan,
                             cutcell::view3d::SceneModel* out, QString* why) const {
#ifdef CUTCELL_HAVE_VIEW3D
    (void)why;
    *out = cutcell::view3d::buildRobotScene(job, plan);
    return true;
#else
    (void)job, (void)plan, (void)out;
    if (why) *why = QObject::tr("3D view not built in this configuration.");
    return false;
#endif
}

} // namespace CutCell::ui
