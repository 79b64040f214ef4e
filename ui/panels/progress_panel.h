#pragma once
// Cut progress: bar, percent, elapsed and remaining time, current point / total, and the
// engine state in words.
//
// Threading contract: GUI thread only.
#include "core/engine/engine_types.h"

#include <QWidget>

class QLabel;
class QProgressBar;

namespace CutCell::ui {

class ProgressPanel : public QWidget {
    Q_OBJECT
  public:
    explicit ProgressPanel(QWidget* parent = nullptr);

    void setSample(const cutcell::TelemetrySample& s);
    void setPlannedTotals(std::uint32_t points, double duration_s);
    void clear();

    QProgressBar* bar() const { return bar_; }
    QString percentText() const;
    QString pointsText() const;
    static QString formatDuration(double seconds);

  private:
    QLabel* state_;
    QProgressBar* bar_;
    QLabel* percent_;
    QLabel* elapsed_;
    QLabel* remaining_;
    QLabel* points_;
};

} // namespace CutCell::ui
