#pragma once
// Run progress: bar, percent, elapsed and remaining time, the current point, piece or stroke of
// the total (the program's terms, run_words.h), the engine state in words, the last cycle time
// and what was made for this job (parts, pieces, strokes).
//
// A run that ends short (emergency stop, fault, abort) keeps its figures on screen with a
// "stopped at" line (point, path length, time) until the next Start: the engine's telemetry
// reads 0 there, the operator needs to know where the torch stopped. During the approach to the
// first cut point the state line says how far the approach is (the cut's own progress is 0).
//
// Threading contract: GUI thread only.
#include "core/engine/engine_types.h"
#include "core/engine/run_terms.h"

#include <QWidget>

#include <optional>

class QLabel;
class QProgressBar;

namespace CutCell::ui {

class ProgressPanel : public QWidget {
    Q_OBJECT
  public:
    explicit ProgressPanel(QWidget* parent = nullptr);

    void setSample(const cutcell::TelemetrySample& s);
    void setPlannedTotals(std::uint32_t points, double duration_s);
    // The path's length (mm) for the stop line, and the first set-point of the cut (the
    // approach's target, in the engine's units).
    void setPathLength(double mm) { pathLengthMm_ = mm; }
    void setApproachTarget(const cutcell::JointVector& q, int axisCount);
    // How the loaded program counts its work (points, pieces, strokes) and names its tool.
    void setTerms(const cutcell::RunTerms& terms);
    // A new run: the previous run's figures and stop line go.
    void beginRun();
    // The run ended short: freeze the last figures and show where it stopped.
    void markStopped(const QString& how);
    // The engine's stop point of that run (arrives just after markStopped): its figures replace
    // those of the last telemetry sample shown.
    void setStopPoint(const cutcell::RunStopPoint& stop);
    // A new program was loaded: the previous run's figures and stop line go, the plan's totals
    // (setPlannedTotals: points, pieces or strokes, the planned duration) show.
    void setProgram(const cutcell::RunTerms& terms, double pathLengthMm);
    void setCycleFigures(int parts, double lastCycleS);
    void clear();

    QProgressBar* bar() const { return bar_; }
    QString percentText() const;
    QString pointsText() const;
    QString remainingText() const;
    QString stateText() const;
    QString stopText() const; // empty when no stop is shown
    QString cycleText() const;
    static QString formatDuration(double seconds);

  private:
    void show(const cutcell::TelemetrySample& s);
    void showStop(const cutcell::RunStopPoint& at);

    QLabel* state_;
    QProgressBar* bar_;
    QLabel* percent_;
    QLabel* elapsed_;
    QLabel* remaining_;
    QLabel* points_;
    QLabel* pointsCaption_ = nullptr;
    QLabel* stop_;
    QLabel* cycle_;
    double pathLengthMm_ = 0;
    cutcell::RunTerms terms_;
    int made_ = 0;
    double lastCycleS_ = 0;
    cutcell::JointVector approachTarget_ = cutcell::JointVector::Zero();
    int axisCount_ = 0;
    std::optional<double> approachStart_; // distance to the target when the approach began
    std::optional<cutcell::TelemetrySample> lastCut_; // the last sample of the current run
    bool stopped_ = false;
    std::uint32_t plannedPoints_ = 0;
    double plannedS_ = 0;
    QString stopHow_;
};

} // namespace CutCell::ui
