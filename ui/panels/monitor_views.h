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

#include <QWidget>

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

  private:
    cutcell::view3d::CellView* view_ = nullptr;
};

class PlotsPanel : public QWidget {
    Q_OBJECT
  public:
    explicit PlotsPanel(QWidget* parent = nullptr);

    void setAxisNames(const QStringList& names);
    void append(const std::vector<cutcell::TelemetrySample>& batch);
    void clear();
    void setPaused(bool paused);
    bool exportPng(const QString& path, QString* error);
    bool exportCsv(const QString& path, QString* error);
    // Samples handed to the plots since the last clear().
    std::uint64_t samplesAppended() const { return appended_; }
    cutcell::plots::TrackingPlotsWidget* plots() const { return plots_; }

  private:
    cutcell::plots::TrackingPlotsWidget* plots_ = nullptr;
    std::uint64_t appended_ = 0;
};

} // namespace CutCell::ui
