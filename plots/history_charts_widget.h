#pragma once
// The production record's two charts (issue 25's History view): each run's cycle time in run
// order, and the alarm Pareto - each alarm's count as a bar, most frequent first, with the
// cumulative share as a line on a 0-100 % axis. QCustomPlot stays behind the pimpl; tick
// labels in the C locale (decimal point), whatever the default locale.
//
// Threading contract: GUI thread only.
#include <QString>
#include <QWidget>

#include <memory>
#include <vector>

namespace cutcell::plots {

struct CycleBar {
    QString label; // the run's id, shown under its bar
    double seconds = 0;
    bool completed = true; // drawn in the completed colour, else in the stopped one
};

struct ParetoBar {
    QString label; // the alarm's text, shortened for the axis
    int count = 0;
};

class HistoryChartsWidget : public QWidget {
    Q_OBJECT
  public:
    explicit HistoryChartsWidget(QWidget* parent = nullptr);
    ~HistoryChartsWidget() override;

    void setCycleTimes(const std::vector<CycleBar>& runs);
    // Sorted here, most frequent first; at most `keep` bars (the rest as "other").
    void setAlarms(std::vector<ParetoBar> alarms, int keep = 8);
    // What the Pareto shows, in its order (tests).
    std::vector<ParetoBar> paretoShown() const;
    // The cumulative share after each bar, 0-100 (tests).
    std::vector<double> paretoCumulative() const;
    bool savePng(const QString& path, int width, int height);

  private:
    struct Impl;
    std::unique_ptr<Impl> d_;
};

} // namespace cutcell::plots
