#include "ui/panels/monitor_views.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"

#include <QLabel>
#include <QVBoxLayout>

#ifdef CUTCELL_HAVE_VIEW3D
#include "ui/view3d/cell_view.h"
#include "ui/view3d/profile_scene.h"
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
    view_ = new cutcell::view3d::CellView(this);
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

void CellViewPanel::setPlan(const std::shared_ptr<const cutcell::CutPlan>& plan,
                            const cutcell::Job& job) {
#ifdef CUTCELL_HAVE_VIEW3D
    if (!view_ || !plan) return;
    if (job.machine == cutcell::kProfileCutterId) {
        try {
            view_->setScene(cutcell::view3d::buildProfileCutterScene(job));
        } catch (const std::exception&) {
            // No cut to draw; the plan's problem is reported by the run controller.
        }
    } else
        view_->setScene(cutcell::view3d::buildRobotScene(job, *plan));
#else
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
        view_->setMachineState(s.actual, s.progress, s.torch_on);
        sinceFrame_.start();
        lastTorch_ = s.torch_on;
    }
#else
    (void)s;
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

void PlotsPanel::setAxisNames(const QStringList& names) {
#ifdef CUTCELL_HAVE_PLOTS
    plots_->setAxisNames(names);
    plots_->setAxisCount(static_cast<int>(names.size()));
#else
    (void)names;
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
        lastPlottedS_ = s.elapsed_s;
#ifdef CUTCELL_HAVE_PLOTS
        double err[cutcell::kAxisCount];
        for (int i = 0; i < cutcell::kAxisCount; ++i)
            err[i] = linear_[size_t(i)] ? s.error[i] : cutcell::rad2deg(s.error[i]);
        const double cart[3] = {s.cartesian_error_mm.x(), s.cartesian_error_mm.y(),
                                s.cartesian_error_mm.z()};
        plots_->append(s.elapsed_s, err, cutcell::kAxisCount, cart);
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
