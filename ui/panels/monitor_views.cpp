#include "ui/panels/monitor_views.h"

#include <QLabel>
#include <QPainter>
#include <QVBoxLayout>

#include <limits>

#ifdef CUTCELL_HAVE_VIEW3D
#include "ui/view3d/cell_scene.h"
#include "ui/view3d/cell_view.h"
#include "ui/view3d/scene_model.h"
#endif
#ifdef CUTCELL_HAVE_PLOTS
#include "plots/tracking_plots_widget.h"
#endif

#include <cmath>

namespace CutCell::ui {

CellViewPanel::CellViewPanel(QWidget* parent) : QWidget(parent) {
    setObjectName("cellViewPanel");
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
#ifdef CUTCELL_HAVE_VIEW3D
    // The view brings its own preset toolbar and, without OpenGL, its own placeholder.
    // A native GL window: the operator column and the plots never wait on a 3D composition.
    view_ = new cutcell::view3d::CellView(this, cutcell::view3d::CellView::Surface::NativeWindow);
    v->addWidget(view_, 1);
#else
    auto* note = new QLabel(tr("3D view not built in this configuration."), this);
    note->setObjectName("viewPlaceholder");
    note->setAlignment(Qt::AlignCenter);
    v->addWidget(note, 1);
#endif
}

bool CellViewPanel::rendering() const {
#ifdef CUTCELL_HAVE_VIEW3D
    return view_ && view_->rendering();
#else
    return false;
#endif
}

void CellViewPanel::paintFrameInto(QImage& shot, const QWidget* grabbed) {
#ifdef CUTCELL_HAVE_VIEW3D
    QWidget* area = view_ ? view_->renderArea() : nullptr;
    if (!area || !area->isVisible()) return;
    const QImage frame = view_->grabFrame();
    if (frame.isNull()) return;
    QPainter painter(&shot);
    painter.drawImage(QRect(area->mapTo(grabbed, QPoint(0, 0)), area->size()), frame);
#else
    (void)shot;
    (void)grabbed;
#endif
}

void CellViewPanel::setPlan(const MachineUi& machine,
                            const std::shared_ptr<const cutcell::MachinePlan>& plan,
                            const cutcell::Job& job) {
#ifdef CUTCELL_HAVE_VIEW3D
    if (!view_ || !plan) return;
    cutcell::view3d::SceneModel model;
    QString why; // no cut to draw: the plan's problem is reported by the run controller
    if (machine.buildScene(job, *plan, &model, &why)) view_->setScene(model);
#else
    (void)machine;
    (void)plan;
    (void)job;
#endif
}

void CellViewPanel::setSample(const cutcell::TelemetrySample& s) {
#ifdef CUTCELL_HAVE_VIEW3D
    // Throttled, except for the moments that matter (torch switching, end of the path).
    static_assert(kFrameIntervalMs > 0);
    const bool due = !sinceFrame_.isValid() || sinceFrame_.elapsed() >= kFrameIntervalMs;
    const bool torchChanged = s.torch_on != lastTorch_;
    if (view_ && (due || torchChanged || s.progress >= 1.0)) {
        cutcell::JointVector q = s.actual;
        const int master = view_->scene().model().masterSlot;
        if (master >= 0 && master < cutcell::kMaxAxes) q[master] = s.master_position;
        view_->setMachineState(q, s.progress, s.torch_on);
        sinceFrame_.start();
        lastTorch_ = s.torch_on;
    }
#else
    (void)s;
#endif
}

void CellViewPanel::setToolName(const QString& name) {
#ifdef CUTCELL_HAVE_VIEW3D
    if (view_) view_->setToolName(name);
#else
    (void)name;
#endif
}

void CellViewPanel::setStopMark(double progressFraction) {
#ifdef CUTCELL_HAVE_VIEW3D
    if (view_) view_->setStopMark(progressFraction);
#else
    (void)progressFraction;
#endif
}

PlotsPanel::PlotsPanel(QWidget* parent) : QWidget(parent) {
    setObjectName("plotsPanel");
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
#ifdef CUTCELL_HAVE_PLOTS
    plots_ = new cutcell::plots::TrackingPlotsWidget(this);
    plots_->setHostDrivenRedraw(true); // drawn in the main window's display frame (redraw())
    v->addWidget(plots_);
#else
    auto* note = new QLabel(tr("Tracking plots not built in this configuration."), this);
    note->setAlignment(Qt::AlignCenter);
    v->addWidget(note);
#endif
}

void PlotsPanel::setMachine(const MachineUi& machine) {
    if (machine.id() == machine_) return;
    machine_ = machine.id();
    setChannels(machine.axes(), machine.tipErrorPlot());
}

void PlotsPanel::setChannels(const std::vector<AxisLabel>& axes, TipErrorPlot tip) {
    axes_ = axes;
    if (axes_.size() > size_t(cutcell::kMaxAxes)) axes_.resize(size_t(cutcell::kMaxAxes));
    tip_ = tip;
    applyChannels();
}

namespace {
// The torch height traces' unit key: their own plot, apart from axes in mm.
const QString kTorchHeightUnit = QStringLiteral("mm torch");
constexpr int kProcessTraces = 3; // arc voltage, standoff error, THC correction
} // namespace

void PlotsPanel::applyChannels() {
    appended_ = 0;
    lastPlottedS_ = -1;
#ifdef CUTCELL_HAVE_PLOTS
    QStringList names, units;
    for (const AxisLabel& a : axes_) {
        names << a.name;
        units << a.unit;
    }
    if (process_) {
        names << tr("arc voltage") << tr("standoff error") << tr("THC correction");
        units << QStringLiteral("V") << kTorchHeightUnit << kTorchHeightUnit;
        plots_->setSignalPlot(QStringLiteral("V"), tr("arc voltage (V)"));
        plots_->setSignalPlot(kTorchHeightUnit, tr("torch height (mm)"));
    }
    plots_->setAxes(names, units);
    switch (tip_) {
    case TipErrorPlot::None:
        plots_->setTipTraces({}, {});
        break;
    case TipErrorPlot::BaseXyz:
        plots_->setTipTraces({"x", "y", "z"}, tr("Cartesian error (mm)"));
        break;
    case TipErrorPlot::MissOnPipe:
        plots_->setTipTraces({tr("torch miss on the pipe")}, tr("miss (mm)"));
        break;
    }
#endif
}

void PlotsPanel::append(const std::vector<cutcell::TelemetrySample>& batch) {
    for (const auto& s : batch) {
        // Only the cut itself is plotted, once the path has begun (approach, settling,
        // homing and rest are not tracking errors of the cut); t is the time since Start.
        const bool cutting =
            s.state == cutcell::EngineState::Running || s.state == cutcell::EngineState::Paused;
        if (!cutting || s.progress <= 0) continue;
        if (lastPlottedS_ >= 0 && s.elapsed_s >= lastPlottedS_ &&
            s.elapsed_s - lastPlottedS_ < kPlotIntervalS - 1e-9)
            continue;
        // A run with a torch height control shows its signals (a run without: not).
        if (s.process.present != process_) {
            process_ = s.process.present;
            applyChannels();
        }
        lastPlottedS_ = s.elapsed_s;
#ifdef CUTCELL_HAVE_PLOTS
        double err[cutcell::kMaxAxes + kProcessTraces];
        int n = static_cast<int>(axes_.size());
        for (int i = 0; i < n; ++i)
            err[i] = axes_[size_t(i)].linear() ? s.error[i] : cutcell::rad2deg(s.error[i]);
        if (process_) {
            const double none = std::numeric_limits<double>::quiet_NaN(); // no arc: a gap
            err[n++] = s.process.arc_ok ? s.process.arc_voltage_v : none;
            err[n++] = s.process.arc_ok ? s.process.height_error_mm : none;
            err[n++] = s.process.correction_mm;
        }
        double tip[3] = {s.cartesian_error_mm.x(), s.cartesian_error_mm.y(),
                         s.cartesian_error_mm.z()};
        if (tip_ == TipErrorPlot::MissOnPipe) tip[0] = s.cartesian_error_mm.norm();
        plots_->append(s.elapsed_s, err, n, tip_ == TipErrorPlot::None ? nullptr : tip);
#endif
        ++appended_;
    }
}

void PlotsPanel::redraw() {
#ifdef CUTCELL_HAVE_PLOTS
    plots_->redrawPending();
#endif
}

void PlotsPanel::clear() {
    appended_ = 0;
    lastPlottedS_ = -1;
#ifdef CUTCELL_HAVE_PLOTS
    plots_->clear();
#endif
}

void PlotsPanel::setPaused(bool paused) {
#ifdef CUTCELL_HAVE_PLOTS
    plots_->setPaused(paused);
#else
    (void)paused;
#endif
}

void PlotsPanel::setSavePathAsker(
    std::function<QString(const QString& title, const QString& tail, const QString& filter)> ask) {
#ifdef CUTCELL_HAVE_PLOTS
    plots_->setSavePathAsker(std::move(ask));
#else
    (void)ask;
#endif
}

bool PlotsPanel::exportPng(const QString& path, QString* error) {
#ifdef CUTCELL_HAVE_PLOTS
    return plots_->exportPng(path, error);
#else
    (void)path;
    if (error) *error = tr("plots not built");
    return false;
#endif
}

bool PlotsPanel::exportCsv(const QString& path, QString* error) {
#ifdef CUTCELL_HAVE_PLOTS
    return plots_->exportCsv(path, error);
#else
    (void)path;
    if (error) *error = tr("plots not built");
    return false;
#endif
}

} // namespace CutCell::ui
