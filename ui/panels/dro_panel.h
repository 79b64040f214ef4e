#pragma once
// The position readout (DRO) of every axis of the loaded program: name with its unit (deg for
// rotary axes, mm for linear ones, from the program's axis names and linear flags), commanded
// and actual position; below it one jog row (axis, - / +, step) that fits the operator column.
// Jog: with a step chosen, each press of - / + moves the axis by that step; with "continuous"
// the axis moves while the button is held (toward its limit) and stops when it is released. The
// engine checks the axis limits and refuses a jog outside them with the reason (event log). Jogging
// is offered only while Ready.
//
// Threading contract: GUI thread only. setSample() only sets label texts (no layout change).
#include "core/engine/engine_types.h"
#include "core/engine/motion_program.h"
#include "ui/machine/machine_ui.h"

#include <QWidget>

#include <array>
#include <memory>
#include <vector>

class QComboBox;
class QGridLayout;
class QLabel;
class QPushButton;

namespace CutCell::ui {

class DroPanel : public QWidget {
    Q_OBJECT
  public:
    explicit DroPanel(QWidget* parent = nullptr);

    // Names and units from the machine UI's labels where given (axis i = label i), else from
    // the program's axis names and linear flags.
    void setProgram(const std::shared_ptr<const cutcell::MotionProgram>& program,
                    const std::vector<AxisLabel>& labels = {});
    void setSample(const cutcell::TelemetrySample& s);
    void setState(cutcell::EngineState state);

    int axisCount() const { return axes_; }
    QString axisName(int axis) const;
    QString unit(int axis) const;
    // The shown values (in the axis's unit) and their texts.
    double commanded(int axis) const;
    double actual(int axis) const;
    QString commandedText(int axis) const;
    QString actualText(int axis) const;
    // The engine's value (rad or mm) in the unit shown for this axis.
    double toDisplay(int axis, double engineValue) const;
    static constexpr int kDecimals = 3;

    // Jog step in the axis unit; 0 = continuous while pressed.
    void setJogStep(double step);
    double jogStep() const;
    void setJogAxis(int axis);
    int jogAxis() const;
    QPushButton* jogButton(int direction) const { return direction < 0 ? minus_ : plus_; }

  signals:
    void jogRequested(int axis, double delta); // engine units (rad or mm)
    void jogContinuousRequested(int axis, int direction);
    void jogStopRequested();

  private:
    struct Row {
        QLabel* name = nullptr;
        QLabel* commanded = nullptr;
        QLabel* actual = nullptr;
    };
    void onPressed(int direction);
    void onReleased();
    void refreshEnabled();

    QGridLayout* grid_;
    QComboBox* step_;
    QComboBox* axis_;
    QPushButton* minus_;
    QPushButton* plus_;
    std::array<QString, cutcell::kMaxAxes> names_{};
    std::array<Row, cutcell::kMaxAxes> rows_{};
    std::array<bool, cutcell::kMaxAxes> linear_{};
    std::array<double, cutcell::kMaxAxes> commanded_{};
    std::array<double, cutcell::kMaxAxes> actual_{};
    int axes_ = 0;
    cutcell::EngineState state_ = cutcell::EngineState::Idle;
    bool continuousHeld_ = false;
};

} // namespace CutCell::ui
