#pragma once
// The two monitoring views of the main window, each behind a small panel so the window does
// not depend on how they are built: the 3D cell view (VTK, CutCell::view3d) with its view
// presets, and the tracking-error plots (QCustomPlot, CutCell::plots). Where OpenGL is not
// available (offscreen platform) the 3D panel shows a note instead of crashing.
//
// Threading contract: GUI thread only.
#include "core/engine/engine_types.h"
#include "core/job/job.h"
#include "core/machine/machine_module.h"
#include "ui/machine/machine_ui.h"

#include <functional>

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

    // The machine's scene for the plan (nothing changes when the machine cannot draw it).
    void setPlan(const MachineUi& machine, const std::shared_ptr<const cutcell::MachinePlan>& plan,
                 const cutcell::Job& job);
    void setSample(const cutcell::TelemetrySample& s);
    // Where the last run stopped, marked on the path (fraction of the cut; < 0: none).
    void setStopMark(double progressFraction);
    void setToolName(const QString& name); // the 3D view's status line
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

    // The machine's channels: one trace per axis with its name, grouped by unit (deg: the
    // engine's rad converted; mm: as is), and its tip error plot; a run with a torch height
    // control adds its arc voltage and torch height plots (from its first sample). Clears the data,
    // so only when the machine differs from the last one set.
    void setMachine(const MachineUi& machine);
    void setChannels(const std::vector<AxisLabel>& axes, TipErrorPlot tip);
    const std::vector<AxisLabel>& axes() const { return axes_; }
    // Cheap: copies into the plots' ring; redraw() draws what was appended.
    void append(const std::vector<cutcell::TelemetrySample>& batch);
    void redraw();
    void clear();
    void setPaused(bool paused);
    // The plots' own Export buttons ask here (TrackingPlotsWidget::setSavePathAsker).
    void setSavePathAsker(
        std::function<QString(const QString& title, const QString& tail, const QString& filter)>
            ask);
    bool exportPng(const QString& path, QString* error);
    bool exportCsv(const QString& path, QString* error);
    // The plots get at most one sample per kPlotIntervalS of engine time (250 Hz): a 30 s
    // cut is then 7 500 points per trace, which the plot redraws at 30 Hz cheaply.
    static constexpr double kPlotIntervalS = 0.004;
    // Samples handed to the plots since the last clear().
    std::uint64_t samplesAppended() const { return appended_; }
    cutcell::plots::TrackingPlotsWidget* plots() const { return plots_; }

  private:
    void applyChannels(); // the axes, the process's signals (process_) and the tip plot
    cutcell::plots::TrackingPlotsWidget* plots_ = nullptr;
    bool process_ = false; // the last run's samples carried a torch height control's signals
    std::uint64_t appended_ = 0;
    std::string machine_;
    std::vector<AxisLabel> axes_;
    TipErrorPlot tip_ = TipErrorPlot::BaseXyz;
    double lastPlottedS_ = -1;
};

} // namespace CutCell::ui
