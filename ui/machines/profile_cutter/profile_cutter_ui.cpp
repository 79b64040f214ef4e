#include "ui/machines/profile_cutter/profile_cutter_ui.h"
#include "ui/shown_number.h"

#include "core/job/job_io.h"
#include "core/machines/profile_cutter/gcode_export.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/profile_cutter_program.h"
#include "ui/machines/profile_cutter/profile_cutter_form.h"

#include <QFile>
#include <QObject>

#include <stdexcept>

#ifdef CUTCELL_HAVE_VIEW3D
#include "ui/machines/profile_cutter/profile_scene.h"
#endif

// The resources live in a static library: initialise them explicitly (as theme.cpp does).
static void initUiResources() {
    Q_INIT_RESOURCE(ui_resources);
}

namespace CutCell::ui {

QString ProfileCutterUi::title() const {
    return QObject::tr("2-axis NC pipe profile cutter: chuck A + carriage X");
}

cutcell::Job ProfileCutterUi::defaultJob() const {
    // The shipped example job (resources/jobs), compiled into the ui's resources.
    initUiResources();
    QFile file(QStringLiteral(":/cutcell/jobs/profile_cutter_job.json"));
    if (!file.open(QIODevice::ReadOnly))
        throw std::runtime_error("the profile cutter's default job is missing from the resources");
    cutcell::Job job = cutcell::parseJob(file.readAll().toStdString());
    job.machine = kId;
    return job;
}

std::vector<FormPage> ProfileCutterUi::formPages() const {
    return {{QObject::tr("Profile cutter"),
             [](JobEditor* e) -> JobForm* { return new ProfileCutterForm(e); }}};
}

std::vector<std::pair<std::string, QString>> ProfileCutterUi::unusedCommonFields() const {
    const QString radial = QObject::tr("The profile cutter's torch stands radial: no bevel.");
    return {{"cut.bevel_deg", radial},
            {"cut.max_direction_deviation_deg",
             QObject::tr("The profile cutter's torch never tilts: no deviation limit.")}};
}

std::vector<ExportKind> ProfileCutterUi::exports() const {
    return {ExportKind::Gcode, ExportKind::TemplateSvg, ExportKind::TemplatePdf};
}

std::string ProfileCutterUi::exportText(ExportKind kind, const cutcell::Job& job,
                                        QString* what) const {
    if (kind != ExportKind::Gcode) return MachineUi::exportText(kind, job, what);
    const cutcell::ProfileCut cut = cutcell::computeProfileCut(job);
    if (const std::string travel = cutcell::travelProblem(job, cut); !travel.empty())
        throw std::invalid_argument(travel);
    cutcell::GcodeStats st;
    std::string text = cutcell::profileGcode(job, cut, &st);
    if (what)
        *what = QObject::tr("G-code (X/A): %1 moves, %2 mm developed, %3 s")
                    .arg(st.moves)
                    .arg(shownNumber(st.length_mm, 1))
                    .arg(shownNumber(st.time_s, 1));
    return text;
}

cutcell::JointExtras ProfileCutterUi::jointExtras(const cutcell::Job& job) const {
    return cutcell::jointExtrasOf(job);
}

QString ProfileCutterUi::planSummary(const cutcell::Job& job,
                                     const cutcell::MachinePlan& plan) const {
    if (!plan.program) return MachineUi::planSummary(job, plan);
    return QObject::tr("Profile cutter: %1 points, %2 mm in %3 s.")
        .arg(plannedPointCount(plan))
        .arg(shownNumber(plan.program->length_mm, 1))
        .arg(shownNumber(plan.program->cut_time_s, 1));
}

bool ProfileCutterUi::buildScene(const cutcell::Job& job, const cutcell::MachinePlan&,
                                 cutcell::view3d::SceneModel* out, QString* why) const {
#ifdef CUTCELL_HAVE_VIEW3D
    try {
        *out = cutcell::view3d::buildProfileCutterScene(job);
        return true;
    } catch (const std::exception& e) {
        // No cut to draw; the plan's problem is reported by the run controller.
        if (why) *why = QString::fromUtf8(e.what());
        return false;
    }
#else
    (void)job, (void)out;
    if (why) *why = QObject::tr("3D view not built in this configuration.");
    return false;
#endif
}

} // namespace CutCell::ui
