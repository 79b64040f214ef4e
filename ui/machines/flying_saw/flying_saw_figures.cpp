#include "ui/machines/flying_saw/flying_saw_figures.h"
#include "ui/forms/issue_text.h"
#include "ui/panels/engine_text.h"
#include "ui/shown_number.h"

#include "core/common/types.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/machines/flying_saw/flying_saw_module.h"
#include "core/machines/flying_saw/saw_csv.h"
#include "core/machines/flying_saw/saw_simulation.h"
#include "plots/xy_figures_widget.h"

#include <QFileDialog>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>

namespace CutCell::ui {

using cutcell::plots::XyCurve;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The seven periods in the order of a cycle, each with its colour on the three carriage panels.
struct PeriodStyle {
    const char* name;
    QColor colour;
};
const std::array<PeriodStyle, 7> kPeriods{{{"AB", QColor(120, 120, 120)},
                                           {"BC", QColor(30, 110, 220)},
                                           {"CE", QColor(20, 160, 70)},
                                           {"EF", QColor(230, 140, 20)},
                                           {"FG", QColor(200, 40, 40)},
                                           {"GH", QColor(150, 60, 180)},
                                           {"HI", QColor(30, 170, 190)}}};

int periodIndex(const char* p) {
    for (size_t i = 0; i < kPeriods.size(); ++i)
        if (std::strcmp(kPeriods[i].name, p) == 0) return static_cast<int>(i);
    return 0;
}

// The module's plan of the edited job (as the run controller and the CLI get it), or why not:
// the first validation issue (key, value, unit, limit) or the plan's refusal with its figures.
bool planOf(const JobEditor& editor, cutcell::MachinePlan* out, QString* problem) {
    const cutcell::Job& job = editor.job();
    const cutcell::MachineModule* module = cutcell::findMachine(cutcell::kFlyingSawId);
    if (!module || !job.machine_spec.as<cutcell::FlyingSawSpec>()) {
        *problem = FlyingSawFiguresForm::tr("the job is not for the flying saw");
        return false;
    }
    if (!editor.issues().empty()) {
        *problem = issueText(editor.issues().front(), QString());
        return false;
    }
    *out = module->plan(job, {});
    if (!out->ok() || !out->data) {
        *problem = engineText(QString::fromStdString(out->outcome.message));
        return false;
    }
    return true;
}

} // namespace

FlyingSawFiguresForm::FlyingSawFiguresForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent) {
    // One above the other: side by side the German texts needed 533 px, the pane at 1280x720
    // shows 424.
    auto* buttons = new QVBoxLayout;
    simulate_ = new QPushButton(tr("Plan and simulate the queue"), this);
    simulate_->setObjectName("sawSimulate");
    export_ = new QPushButton(tr("Export cam table CSV…"), this);
    export_->setObjectName("sawExportCam");
    buttons->addWidget(simulate_);
    buttons->addWidget(export_);
    mainLayout()->addLayout(buttons);
    summary_ = new QLabel(tr("Not simulated yet."), this);
    summary_->setObjectName("sawSummary");
    summary_->setWordWrap(true);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    stats_ = new QLabel(this);
    stats_->setObjectName("sawPieceStats");
    stats_->setWordWrap(true);
    stats_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    figures_ = new cutcell::plots::XyFiguresWidget(PanelCount, Qt::Vertical, this);
    figures_->setLegendColumns(CarriageS, 4); // the periods' colours, alike on s, v and a
    figures_->setLegendColumns(CarriageV, 0);
    figures_->setLegendColumns(CarriageA, 0);
    figures_->setPanel(CarriageS, tr("Carriage position over one cycle (nominal line speed)"),
                       tr("t (s)"), tr("s (mm)"));
    figures_->setPanel(CarriageV, tr("Carriage velocity"), tr("t (s)"), tr("v (mm/s)"));
    figures_->setPanel(CarriageA, tr("Carriage acceleration"), tr("t (s)"), tr("a (mm/s²)"));
    figures_->setPanel(Cam, tr("Cam table: radial feed against the turntable angle"),
                       tr("turntable θ (deg)"), tr("feed (mm)"));
    figures_->setPanel(Pieces, tr("Cut length error of every piece (simulated queue)"), tr("piece"),
                       tr("length - ordered (mm)"));
    mainLayout()->addWidget(summary_);
    mainLayout()->addWidget(stats_);
    mainLayout()->addWidget(figures_, 1);
    connect(simulate_, &QPushButton::clicked, this, [this] { simulate(); });
    connect(export_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Export the cam table"), QStringLiteral("cam.csv"), tr("CSV files (*.csv)"));
        if (path.isEmpty()) return;
        QString error;
        if (!exportCamCsv(path, &error))
            summary_->setText(error);
        else
            summary_->setText(tr("Cam table written to %1.").arg(path));
    });
}

bool FlyingSawFiguresForm::simulate(QString* why) {
    cutcell::MachinePlan mp;
    QString problem;
    if (!planOf(*editor(), &mp, &problem)) {
        summary_->setText(tr("Cannot plan: %1").arg(problem));
        stats_->clear();
        for (int p = 0; p < PanelCount; ++p)
            figures_->setCurves(p, {});
        if (why) *why = summary_->text();
        return false;
    }
    const auto& d = *static_cast<const cutcell::FlyingSawPlanData*>(mp.data.get());
    const cutcell::FlyingSawPlan& plan = d.plan;

    // One cycle, each period its own curve on s, v and a.
    std::array<std::vector<XyCurve>, 3> carriage;
    for (auto& panel : carriage)
        for (const PeriodStyle& p : kPeriods)
            panel.push_back({QString::fromLatin1(p.name), {}, {}, p.colour});
    int last = -1;
    for (const cutcell::CycleRow& r : cutcell::nominalCycle(plan, 0.002)) {
        const int i = periodIndex(r.period);
        const double values[3] = {r.s, r.v, r.a};
        for (int k = 0; k < 3; ++k) {
            XyCurve& c = carriage[static_cast<size_t>(k)][static_cast<size_t>(i)];
            if (i != last && !c.x.isEmpty()) c.x.push_back(kNaN), c.y.push_back(kNaN); // AB twice
            c.x.push_back(r.t), c.y.push_back(values[k]);
        }
        last = i;
    }
    figures_->setCurves(CarriageS, carriage[0]);
    figures_->setCurves(CarriageV, carriage[1]);
    figures_->setCurves(CarriageA, carriage[2]);

    // The cam table: both blades follow the same table, half a turn apart.
    const cutcell::CamTable& cam = plan.saw.cam;
    XyCurve feed{tr("feed, blades 1 and 2"), {}, {}, QColor(20, 90, 200)};
    XyCurve tip{tr("blade tip radius"), {}, {}, QColor(220, 60, 30), true};
    for (int i = 0; i < cam.count; ++i) {
        const double theta = cutcell::rad2deg(cam.period * i / (cam.count - 1));
        const double f = cam.slave[static_cast<size_t>(i)];
        feed.x.push_back(theta), feed.y.push_back(f);
        tip.x.push_back(theta), tip.y.push_back(plan.saw.retract_radius - f);
    }
    figures_->setCurves(Cam, {feed, tip});

    // The queue on the simulated line.
    cutcell::SawSimOptions options;
    options.period_s = editor()->job().sim.period_s > 0 ? editor()->job().sim.period_s : 0.001;
    const cutcell::SawSimResult r = cutcell::simulateFlyingSaw(d.spec, plan, options);
    const double tol = d.spec.tolerance_mm;
    XyCurve err{tr("error"), {}, {}, QColor(20, 90, 200)};
    XyCurve mean{tr("mean"), {}, {}, QColor(30, 140, 60), true};
    XyCurve band{tr("± tolerance"), {}, {}, QColor(200, 40, 40), true};
    for (const cutcell::PieceRecord& p : r.pieces)
        err.x.push_back(p.piece), err.y.push_back(p.error_mm);
    // The tolerance band only where it does not flatten the errors to a line (the stats name
    // it and the Cpk either way).
    const bool showBand = r.stats.max_abs >= 0.2 * tol;
    if (!showBand)
        err.name = tr("error (tolerance ± %1 mm far outside)").arg(shownSignificant(tol, 4));
    if (!r.pieces.empty()) {
        const double x0 = r.pieces.front().piece - 0.5, x1 = r.pieces.back().piece + 0.5;
        mean.x = {x0, x1}, mean.y = {r.stats.mean, r.stats.mean};
        band.x = {x0, x1, kNaN, x0, x1}, band.y = {tol, tol, kNaN, -tol, -tol};
    }
    std::vector<XyCurve> pieceCurves{err, mean};
    if (showBand) pieceCurves.push_back(band);
    figures_->setCurves(Pieces, pieceCurves);

    summary_->setText(QString::fromStdString(mp.summary));
    QString stats = tr("%1 pieces measured: error mean %2 mm, std %3 mm, max |e| %4 mm, Cpk %5 "
                       "(± %6 mm); largest cut spread on the pipe %7 mm.")
                        .arg(r.stats.count)
                        .arg(shownNumber(r.stats.mean, 4))
                        .arg(shownNumber(r.stats.std, 4))
                        .arg(shownNumber(r.stats.max_abs, 4))
                        .arg(shownSignificant(r.stats.cpk, 4))
                        .arg(shownSignificant(tol, 4))
                        .arg(shownNumber(
                            [&] {
                                double m = 0;
                                for (const cutcell::PieceRecord& p : r.pieces)
                                    m = std::max(m, p.spread_mm);
                                return m;
                            }(),
                            3));
    if (!r.completed)
        stats += QLatin1Char(' ') +
                 tr("Not completed: %1").arg(engineText(QString::fromStdString(r.problem)));
    stats_->setText(stats);
    if (!r.completed && why) *why = stats;
    return r.completed;
}

bool FlyingSawFiguresForm::exportCamCsv(const QString& path, QString* error) {
    cutcell::MachinePlan mp;
    QString problem;
    if (!planOf(*editor(), &mp, &problem)) {
        if (error) *error = tr("Cam table not written to %1: %2").arg(path, problem);
        return false;
    }
    try {
        const cutcell::MachineModule& module = *cutcell::findMachine(cutcell::kFlyingSawId);
        cutcell::writeFileAtomically(path.toStdString(),
                                     module.exportFile("cam_csv", editor()->job(), mp));
    } catch (const std::exception& e) {
        if (error)
            *error = tr("Cam table not written to %1: %2").arg(path, QString::fromUtf8(e.what()));
        return false;
    }
    return true;
}

} // namespace CutCell::ui
