#include "ui/machines/quick_return_cutter/quick_return_figures.h"

#include "core/machines/quick_return/quick_return_spec.h"
#include "plots/xy_figures_widget.h"

#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <limits>

namespace CutCell::ui {

using cutcell::plots::XyCurve;

QuickReturnFiguresForm::QuickReturnFiguresForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent) {
    button_ = new QPushButton(tr("Simulate the cut (experiment 2, the job's controller)"), this);
    button_->setObjectName("quickReturnSimulate");
    summary_ = new QLabel(tr("Not simulated yet."), this);
    summary_->setWordWrap(true);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    figures_ = new cutcell::plots::XyFiguresWidget(3, Qt::Vertical, this);
    figures_->setPanel(0, tr("Velocity profile"), tr("t (s)"), tr("y' (m/s)"));
    figures_->setPanel(1, tr("Phase diagram"), tr("y (m)"), tr("y' (m/s)"));
    figures_->setPanel(2, tr("Velocity error in the cut"), tr("y (m)"), tr("y_d' - y' (m/s)"));
    mainLayout()->addWidget(button_);
    mainLayout()->addWidget(summary_);
    mainLayout()->addWidget(figures_, 1);
    connect(button_, &QPushButton::clicked, this, [this] { simulate(); });
}

bool QuickReturnFiguresForm::simulate(QString* why) {
    namespace qr = cutcell::quick_return;
    const cutcell::Job job = editor()->job();
    const cutcell::QuickReturnSpec* spec = job.machine_spec.as<cutcell::QuickReturnSpec>();
    qr::ExperimentSetup setup;
    std::string problem = "the job is not for the quick-return cutter";
    if (!spec || !cutcell::buildSetup(*spec, &setup, &problem)) {
        summary_->setText(tr("Cannot simulate: %1").arg(QString::fromStdString(problem)));
        if (why) *why = summary_->text();
        return false;
    }
    // A few hundred ms of the GUI thread for the default job's three strokes.
    const qr::CuttingResult r = qr::runCutting(setup, spec->controller);
    const double gap = std::numeric_limits<double>::quiet_NaN();
    XyCurve v{tr("y'"), {}, {}, QColor(20, 90, 200)};
    XyCurve vd{tr("y_d'"), {}, {}, QColor(220, 60, 30), true};
    XyCurve phase{tr("y'(y)"), {}, {}, QColor(20, 90, 200)};
    XyCurve phaseD{tr("y_d'(y)"), {}, {}, QColor(220, 60, 30), true};
    XyCurve err{tr("y_d' - y'"), {}, {}, QColor(30, 140, 60)};
    const double workLow = std::min(setup.law.profile.y_a, setup.law.profile.y_b);
    const double workHigh = std::max(setup.law.profile.y_a, setup.law.profile.y_b);
    bool wasCutting = false;
    for (const qr::TracePoint& p : r.trace) {
        v.x.push_back(p.t), v.y.push_back(p.dy);
        vd.x.push_back(p.t), vd.y.push_back(p.dy_d);
        phase.x.push_back(p.y), phase.y.push_back(p.dy);
        // Over the workpiece, as the core's max and RMS count it.
        const bool inWork = p.cutting && p.y >= workLow && p.y <= workHigh;
        if (inWork) {
            phaseD.x.push_back(p.y), phaseD.y.push_back(p.dy_d);
            err.x.push_back(p.y), err.y.push_back(p.dy_d - p.dy);
        } else if (wasCutting) { // a gap between strokes
            err.x.push_back(gap), err.y.push_back(gap);
        }
        wasCutting = inWork;
    }
    figures_->setCurves(0, {v, vd});
    figures_->setCurves(1, {phase, phaseD});
    figures_->setCurves(2, {err});
    QString text = tr("%1: %2 strokes, velocity error in the work max %3 m/s, RMS %4 m/s "
                      "(%5 samples); peak torque %6 N m.")
                       .arg(QString::fromUtf8(qr::toString(spec->controller)))
                       .arg(r.strokes)
                       .arg(r.velocity_error_max, 0, 'f', 4)
                       .arg(r.velocity_error_rms, 0, 'f', 4)
                       .arg(r.samples_in_work)
                       .arg(r.max_torque, 0, 'f', 2);
    if (!r.completed)
        text += QLatin1Char(' ') + tr("Not completed: %1").arg(QString::fromStdString(r.problem));
    summary_->setText(text);
    if (!r.completed && why) *why = text;
    return r.completed;
}

} // namespace CutCell::ui
