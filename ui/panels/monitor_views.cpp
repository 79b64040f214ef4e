#include "ui/panels/monitor_views.h"

#include <QButtonGroup>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#ifdef CUTCELL_HAVE_VIEW3D
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
    v->setSpacing(2);
#ifdef CUTCELL_HAVE_VIEW3D
    if (view3d::CellView::openGlAvailable()) {
        auto* bar = new QHBoxLayout;
        bar->setContentsMargins(4, 2, 4, 0);
        auto* title = new QLabel(tr("Cell"), this);
        title->setObjectName("panelTitle");
        bar->addWidget(title);
        bar->addStretch(1);
        view_ = new view3d::CellView(this);
        const auto preset = [this, bar](const QString& text, view3d::ViewPreset p) {
            auto* b = new QPushButton(text, this);
            b->setObjectName("viewPresetButton");
            b->setFocusPolicy(Qt::NoFocus);
            connect(b, &QPushButton::clicked, view_, [this, p] { view_->setPreset(p); });
            bar->addWidget(b);
        };
        preset(tr("Iso"), view3d::ViewPreset::Iso);
        preset(tr("Front"), view3d::ViewPreset::Front);
        preset(tr("Top"), view3d::ViewPreset::Top);
        preset(tr("Follow torch"), view3d::ViewPreset::FollowTorch);
        auto* reset = new QPushButton(tr("Reset view"), this);
        reset->setObjectName("viewPresetButton");
        reset->setFocusPolicy(Qt::NoFocus);
        connect(reset, &QPushButton::clicked, view_, [this] { view_->resetView(); });
        bar->addWidget(reset);
        v->addLayout(bar);
        v->addWidget(view_, 1);
        return;
    }
#endif
    note_ = new QLabel(tr("3D view not available: no OpenGL 3.2 context on this display "
                          "(offscreen platform).\nThe cut runs and is monitored as usual."),
                       this);
    note_->setObjectName("viewPlaceholder");
    note_->setAlignment(Qt::AlignCenter);
    note_->setWordWrap(true);
    v->addWidget(note_, 1);
}

void CellViewPanel::setPlan(const std::shared_ptr<const cutcell::CutPlan>& plan,
                            const cutcell::Job& job) {
#ifdef CUTCELL_HAVE_VIEW3D
    if (view_ && plan) view_->setScene(view3d::buildRobotScene(job, *plan));
#else
    (void)plan;
    (void)job;
#endif
}

void CellViewPanel::setSample(const cutcell::TelemetrySample& s) {
#ifdef CUTCELL_HAVE_VIEW3D
    if (view_) view_->setMachineState(s.actual, s.progress, s.torch_on);
#else
    (void)s;
#endif
}

PlotsPanel::PlotsPanel(QWidget* parent) : QWidget(parent) {
    setObjectName("plotsPanel");
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
#ifdef CUTCELL_HAVE_PLOTS
    plots_ = new plots::TrackingPlotsWidget(this);
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
        // Only the cut itself is plotted (homing and rest are not tracking errors of the cut).
        if (s.state != cutcell::EngineState::Running && s.state != cutcell::EngineState::Paused)
            continue;
#ifdef CUTCELL_HAVE_PLOTS
        double err[cutcell::kAxisCount];
        for (int i = 0; i < cutcell::kAxisCount; ++i)
            err[i] = cutcell::rad2deg(s.error[i]);
        const double cart[3] = {s.cartesian_error_mm.x(), s.cartesian_error_mm.y(),
                                s.cartesian_error_mm.z()};
        plots_->append(s.elapsed_s, err, cutcell::kAxisCount, cart);
#endif
        ++appended_;
    }
}

void PlotsPanel::clear() {
    appended_ = 0;
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
