#include "ui/machines/quick_return/quick_return_figures.h"
#include "ui/panels/engine_text.h"
#include "ui/shown_number.h"

#include "core/machines/quick_return/quick_return_spec.h"
#include "plots/xy_figures_widget.h"
#include "ui/run_controller.h"

#include <QEvent>
#include <QLabel>
#include <QPushButton>
#include <QThread>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <limits>

namespace CutCell::ui {

namespace qr = cutcell::quick_return;
using cutcell::plots::XyCurve;

namespace {

constexpr int kMaxPlotted = 3000; // points per curve: a long run is thinned evenly

bool runState(cutcell::EngineState s) {
    return s == cutcell::EngineState::Running || s == cutcell::EngineState::Paused;
}

// The offline trace as the run's points, counted over the work as the core counts it.
std::vector<qr::RunFigurePoint> fromTrace(const std::vector<qr::TracePoint>& trace, double lo,
                                          double hi) {
    std::vector<qr::RunFigurePoint> out;
    out.reserve(trace.size());
    for (const qr::TracePoint& p : trace) {
        qr::RunFigurePoint r;
        r.t = p.t, r.y = p.y, r.dy = p.dy, r.y_d = p.y_d, r.dy_d = p.dy_d, r.torque = p.torque;
        r.cutting = p.cutting;
        r.in_work = p.cutting && p.y >= lo && p.y <= hi;
        out.push_back(r);
    }
    return out;
}

} // namespace

QuickReturnFiguresForm::QuickReturnFiguresForm(JobEditor* editor, QWidget* parent)
    : JobForm(editor, parent), run_(qr::QuickReturnLawConfig{}),
      watcher_(new QFutureWatcher<qr::CuttingResult>(this)) {
    button_ =
        new QPushButton(tr("Simulate the cut offline (experiment 2, the job's controller)"), this);
    button_->setObjectName("quickReturnSimulate");
    sourceLabel_ = new QLabel(tr("Figures of the last run on the engine appear here while it "
                                 "runs; or simulate the job's cut offline."),
                              this);
    sourceLabel_->setObjectName("quickReturnFiguresSource");
    sourceLabel_->setWordWrap(true);
    summary_ = new QLabel(tr("No run and no simulation yet."), this);
    summary_->setWordWrap(true);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    figures_ = new cutcell::plots::XyFiguresWidget(3, Qt::Vertical, this);
    figures_->setPanel(0, tr("Velocity profile"), tr("t (s)"), tr("y' (m/s)"));
    figures_->setPanel(1, tr("Phase diagram"), tr("y (m)"), tr("y' (m/s)"));
    figures_->setPanel(2, tr("Velocity error in the work"), tr("y (m)"), tr("y_d' - y' (m/s)"));
    // Inside the phase diagram's loop (the return's hump above, the cut below) nothing is drawn.
    figures_->setLegendAlignment(1, Qt::AlignCenter);
    figures_->setLegendAlignment(2, Qt::AlignBottom | Qt::AlignLeft);
    mainLayout()->addWidget(button_);
    mainLayout()->addWidget(sourceLabel_);
    mainLayout()->addWidget(summary_);
    mainLayout()->addWidget(figures_, 1);
    connect(button_, &QPushButton::clicked, this, [this] { startSimulation(); });
    connect(watcher_, &QFutureWatcher<qr::CuttingResult>::finished, this,
            &QuickReturnFiguresForm::simulationFinished);
}

QuickReturnFiguresForm::~QuickReturnFiguresForm() = default;

bool QuickReturnFiguresForm::event(QEvent* e) {
    // The parameter tabs place the page in the window (a scroll area inside MainWindow):
    // from then on the window's RunController is an ancestor's child.
    if (e->type() == QEvent::ParentChange && !runController_) attachToWindow();
    return JobForm::event(e);
}

void QuickReturnFiguresForm::showEvent(QShowEvent* e) {
    JobForm::showEvent(e);
    if (!runController_) attachToWindow();
    if (dirty_) redraw();
}

void QuickReturnFiguresForm::attachToWindow() {
    for (QWidget* w = parentWidget(); w && !runController_; w = w->parentWidget())
        runController_ = w->findChild<RunController*>(QString(), Qt::FindDirectChildrenOnly);
    if (!runController_) return;
    // The same batches as the main window's tracking plots (EngineBridge::samples).
    connect(runController_->bridge(), &EngineBridge::samples, this,
            &QuickReturnFiguresForm::addSamples);
}

bool QuickReturnFiguresForm::simulating() const {
    return watcher_->isRunning();
}

bool QuickReturnFiguresForm::startSimulation(QString* why) {
    if (simulating()) {
        if (why) *why = tr("a simulation is running");
        return false;
    }
    const cutcell::Job job = editor()->job();
    const cutcell::QuickReturnSpec* spec = job.machine_spec.as<cutcell::QuickReturnSpec>();
    const cutcell::Outcome set =
        spec ? cutcell::buildSetup(*spec, &simSetup_)
             : cutcell::Outcome::refuse("the job is not for the quick-return cutter");
    if (!set.ok()) {
        summary_->setText(tr("Cannot simulate: %1").arg(QString::fromStdString(set.message)));
        if (why) *why = summary_->text();
        return false;
    }
    const qr::ControllerKind controller = spec->controller;
    simController_ = QString::fromUtf8(qr::toString(controller));
    button_->setEnabled(false);
    summary_->setText(tr("Simulating the cut with %1 ...").arg(simController_));
    // A copy of the set-up: the pool thread shares nothing with the page.
    watcher_->setFuture(QtConcurrent::run(
        [setup = simSetup_, controller] { return qr::runCutting(setup, controller); }));
    return true;
}

void QuickReturnFiguresForm::simulationFinished() {
    button_->setEnabled(true);
    const qr::CuttingResult r = watcher_->result();
    source_ = Source::Simulation;
    const double lo = std::min(simSetup_.law.profile.y_a, simSetup_.law.profile.y_b);
    const double hi = std::max(simSetup_.law.profile.y_a, simSetup_.law.profile.y_b);
    draw(fromTrace(r.trace, lo, hi));
    figures_->setPanel(2,
                       tr("Velocity error in the work: max %1, RMS %2 m/s")
                           .arg(shownNumber(r.velocity_error_max, 3))
                           .arg(shownNumber(r.velocity_error_rms, 3)),
                       tr("y (m)"), tr("y_d' - y' (m/s)"));
    sourceLabel_->setText(tr("Source: offline simulation of the job's cut (core runCutting, "
                             "the engine's control law on the crank plant)."));
    QString text = tr("%1: %2 strokes, velocity error in the work max %3 m/s, RMS %4 m/s "
                      "(%5 samples); peak torque %6 N m.")
                       .arg(simController_)
                       .arg(r.strokes)
                       .arg(shownNumber(r.velocity_error_max, 4))
                       .arg(shownNumber(r.velocity_error_rms, 4))
                       .arg(r.samples_in_work)
                       .arg(shownNumber(r.max_torque, 2));
    if (!r.completed)
        text += QLatin1Char(' ') +
                tr("Not completed: %1").arg(engineText(QString::fromStdString(r.problem)));
    summary_->setText(text);
    emit simulated(r.completed);
}

void QuickReturnFiguresForm::addSamples(const std::vector<cutcell::TelemetrySample>& batch) {
    bool ended = false, fed = false;
    for (const cutcell::TelemetrySample& s : batch) {
        if (runState(s.state) && !run_.lastWasRun()) {
            // A run begins: the law it runs (the loaded program's), else not this machine's.
            const qr::QuickReturnLaw* law = nullptr;
            if (runController_ && runController_->program())
                law = dynamic_cast<const qr::QuickReturnLaw*>(
                    runController_->program()->source.get());
            qr::ExperimentSetup setup;
            const auto* spec = editor()->job().machine_spec.as<cutcell::QuickReturnSpec>();
            if (law)
                run_.setLaw(law->config()); // immutable after construction: safe to read
            else if (!runController_ && spec && cutcell::buildSetup(*spec, &setup).ok())
                run_.setLaw(setup.law); // a bare page fed by hand (tests)
            else
                continue; // another machine's run
        } else if (!runState(s.state) && !run_.active()) {
            continue;
        }
        const bool wasActive = run_.active();
        run_.add(s);
        fed = true;
        ended = ended || (wasActive && !run_.active());
        if (run_.active()) source_ = Source::LastRun;
    }
    if (!fed || source_ != Source::LastRun) return;
    dirty_ = true;
    const bool due = ended || !sinceDraw_.isValid() || sinceDraw_.elapsed() >= kLiveRedrawMs;
    if (due && isVisible()) redraw();
}

void QuickReturnFiguresForm::redraw() {
    dirty_ = false;
    if (source_ != Source::LastRun) return;
    sinceDraw_.start();
    const qr::VelocityProfile& p = run_.law().profile;
    const double lo = std::min(p.y_a, p.y_b), hi = std::max(p.y_a, p.y_b);
    draw(run_.points());
    const qr::RunFigureStats st = run_.stats();
    figures_->setPanel(2,
                       tr("Velocity error in the work: max %1, RMS %2 m/s")
                           .arg(shownNumber(st.velocity_error_max, 3))
                           .arg(shownNumber(st.velocity_error_rms, 3)),
                       tr("y (m)"), tr("y_d' - y' (m/s)"));
    sourceLabel_->setText(
        run_.active()
            ? tr("Source: run %1 on the engine, live from its telemetry.").arg(run_.runs())
            : tr("Source: run %1 on the engine (ended), from its telemetry.").arg(run_.runs()));
    summary_->setText(tr("%1: %2 cuts, velocity error in the work [%3, %4] m max %5 m/s, "
                         "RMS %6 m/s (%7 samples); peak torque %8 N m.")
                          .arg(QString::fromUtf8(qr::toString(run_.law().controller)))
                          .arg(st.cuts)
                          .arg(shownNumber(lo, 4))
                          .arg(shownNumber(hi, 4))
                          .arg(shownNumber(st.velocity_error_max, 4))
                          .arg(shownNumber(st.velocity_error_rms, 4))
                          .arg(st.samples_in_work)
                          .arg(shownNumber(st.max_torque, 2)));
    ++redraws_;
    emit runFiguresDrawn();
}

void QuickReturnFiguresForm::draw(const std::vector<qr::RunFigurePoint>& points) {
    const double gap = std::numeric_limits<double>::quiet_NaN();
    XyCurve v{tr("y'"), {}, {}, QColor(20, 90, 200)};
    XyCurve vd{tr("y_d'"), {}, {}, QColor(220, 60, 30), true};
    XyCurve phase{tr("y'(y)"), {}, {}, QColor(20, 90, 200)};
    XyCurve phaseD{tr("y_d'(y)"), {}, {}, QColor(220, 60, 30), true};
    XyCurve err{tr("y_d' - y'"), {}, {}, QColor(30, 140, 60)};
    const size_t step = std::max<size_t>(1, points.size() / kMaxPlotted);
    bool wasInWork = false;
    for (size_t i = 0; i < points.size(); ++i) {
        const qr::RunFigurePoint& p = points[i];
        // Every work point is kept for the error panel; the others are thinned.
        const bool thin = i % step != 0;
        if (!thin) {
            v.x.push_back(p.t), v.y.push_back(p.dy);
            vd.x.push_back(p.t), vd.y.push_back(p.dy_d);
            phase.x.push_back(p.y), phase.y.push_back(p.dy);
        }
        if (p.in_work) {
            if (!thin) phaseD.x.push_back(p.y), phaseD.y.push_back(p.dy_d);
            err.x.push_back(p.y), err.y.push_back(p.dy_d - p.dy);
        } else if (wasInWork) { // a gap between strokes
            err.x.push_back(gap), err.y.push_back(gap);
            phaseD.x.push_back(gap), phaseD.y.push_back(gap);
        }
        wasInWork = p.in_work;
    }
    figures_->setCurves(0, {v, vd});
    figures_->setCurves(1, {phase, phaseD});
    figures_->setCurves(2, {err});
}

} // namespace CutCell::ui
