#pragma once
// Cut recovery (QtPlasmaC's "cut recovery" and "run from line"): after an emergency stop, a
// fault or an abort the panel shows where the torch stopped and offers to run the rest of the
// cut from there, backed off by a lead-in along the path, or from a point the operator picks.
// The engine approaches that point with the torch off, lights and pierces again, and ramps the
// path up from rest (MotionEngine::startFrom). The buttons are refused, with the reason, where
// the machine's motion is not a path in time or the machine is not Ready and homed.
//
// Threading contract: GUI thread only. The panel only emits requests (path time, s).
#include "core/engine/engine_types.h"
#include "core/engine/motion_program.h"

#include <QWidget>

#include <memory>
#include <optional>

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace CutCell::ui {

class RecoveryPanel : public QWidget {
    Q_OBJECT
  public:
    explicit RecoveryPanel(QWidget* parent = nullptr);

    void setProgram(std::shared_ptr<const cutcell::MotionProgram> program);
    // Where the last run stopped; nullopt after a completed run or a new program.
    void setStopPoint(const std::optional<cutcell::RunStopPoint>& stop);
    void setState(cutcell::EngineState state, bool homed);
    // A completed part with stretches no run cut (text: which), shown with "Count the part as
    // good"; empty hides them.
    void setUnconfirmedPart(const QString& text);

    // The path time a request would start at: the stop point minus the lead-in, and the picked
    // point (both clamped to the path).
    double resumePathTime() const;
    double pickedPathTime() const;
    QString reason() const; // why recovery is not offered now ("" when it is)

    QPushButton* resumeButton() const { return resume_; }
    QPushButton* runFromButton() const { return runFrom_; }
    QDoubleSpinBox* leadInField() const { return leadIn_; }
    QSpinBox* pointField() const { return point_; }
    QPushButton* confirmPartButton() const { return confirm_; }

  signals:
    void startFromRequested(double pathTime_s);
    void partConfirmed();

  private:
    void refresh();
    double timeOfPoint(int point) const;
    double leadInTime() const;

    QLabel* where_;
    QLabel* reason_;
    QDoubleSpinBox* leadIn_;
    QSpinBox* point_;
    QPushButton* resume_;
    QPushButton* runFrom_;
    QLabel* unconfirmed_;
    QPushButton* confirm_;
    std::shared_ptr<const cutcell::MotionProgram> program_;
    std::optional<cutcell::RunStopPoint> stop_;
    cutcell::EngineState state_ = cutcell::EngineState::Idle;
    bool homed_ = false;
};

} // namespace CutCell::ui
