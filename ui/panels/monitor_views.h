#pragma once
// The two monitoring views of the main window, each behind a small panel so the window does
// not depend on how they are built: the 3D cell view (VTK, CutCell::view3d) with its view
// presets, and the tracking-error plots (QCustomPlot, CutCell::plots). Where OpenGL is not
// available (offscreen platform) the 3D panel shows a note instead of crashing.
//
// Threading contract: GUI thread only.
#include "core/engine/engine_types.h"
#include "core/job/job.h"
#include "core/trajectory/cut_planner.h"

#include <QElapsedTimer>
#include <QWidget>

#include <array>

#include <memory>
#include <vector>

class QLabel;

namespace cutcell::view3d {
class CellView;
}
namespace cutcell::plots {
class TrackingPlotsWidget;
}

namespace CutCell::ui {

class CellViewPanel : public QWidget {
    Q_OBJECT
  public:
    explicit CellViewPanel(QWidget* parent = nullptr);

    void setPlan(const std::shared_ptr<const cutcell::CutPlan>& plan, const cutcell::Job& job);
    void setSample(const cutcell::TelemetrySample& s);
    bool rendering() const;
    cutcell::view3d::CellView* view() const { return view_; }
    // Paints the current 3D frame over its place in `shot`, an image of `grabbed` taken with
    // QWidget::grab() (which does not see the native GL window).
    void paintFrameInto(QImage& shot, const QWidget* grabbed);

    // The view follows the machine at most this often: each frame costs a render and, with
    // software OpenGL, a composition of the whole window. (The main window feeds it at its
    // display-frame rate, ~15 Hz; this bound keeps other callers from rendering faster.)
    static constexpr int kFrameIntervalMs = 50;

  private:
    cutcell::view3d::CellView* view_ = nullptr;
    QElapsedTimer sinceFrame_;
    bool lastTorch_ = false;
};

class PlotsPanel : public QWidget {
    Q_OBJECT
  public:
    explicit PlotsPanel(QWidget* parent = nullptr);

    void setAxisNames(const QStringList& names);
    // Axes whose error is a length (mm, plotted as is); the others are rad, plotted in deg.
    void setLinearAxes(const std::array<bool, cutcell::kAxisCount>& linear) { linear_ = linear; }
    // Cheap: copies into the plots' ring; redraw() draws what was appended.
    void append(const std::vector<cutcell::TelemetrySample>& batch);
    void redraw();
    void clear();
    void setPaused(bool paused);
    bool exportPng(const QString& path, QString* error);
    bool exportCsv(const QString& path, QString* error);
    // The plots get at most one sample per kPlotIntervalS of engine time (250 Hz): a 30 s
    // cut is then 7 500 points per trace, which the plot redraws at 30 Hz cheaply.
    static constexpr double kPlotIntervalS = 0.004;
    // Samples handed to the plots since the last clear().
    std::uint64_t samplesAppended() const { return appended_; }
    cutcell::plots::TrackingPlotsWidget* plots() const { return plots_; }

  private:
    cutcell::plots::TrackingPlotsWidget* plots_ = nullptr;
    std::uint64_t appended_ = 0;
    std::array<bool, cutcell::kAxisCount> linear_{};
    double lastPlottedS_ = -1;
};

} // namespace CutCell::ui
