#pragma once
// The operator's controls: Enable, Home, Start, Feed hold / Resume, Abort, Reset, the speed
// override slider and the EMERGENCY STOP. The E-STOP button is never disabled and its shortcut
// (F1, Qt::ApplicationShortcut) works whatever widget has the focus, also inside a modal
// dialog (an application event filter takes the key there). The panel only emits
// requests; RunController decides what is allowed and says why Start is not.
//
// Threading contract: GUI thread only.
#include "core/engine/engine_types.h"

#include <QWidget>

class QLabel;
class QPushButton;
class QShortcut;
class QSlider;

namespace CutCell::ui {

class ControlPanel : public QWidget {
    Q_OBJECT
  public:
    static constexpr const char* kEStopKey = "F1";

    explicit ControlPanel(QWidget* parent = nullptr);

    // Buttons follow the engine state; Start also needs `startBlocked` to be empty.
    void setState(cutcell::EngineState state, bool homed);
    void setStartBlocked(const QString& reason);
    void setOverridePercent(int percent);

    QPushButton* eStopButton() const { return eStop_; }
    QPushButton* startButton() const { return start_; }
    QPushButton* enableButton() const { return enable_; }
    QPushButton* homeButton() const { return home_; }
    QPushButton* holdButton() const { return hold_; }
    QPushButton* resumeButton() const { return resume_; }
    QPushButton* abortButton() const { return abort_; }
    QPushButton* resetButton() const { return reset_; }
    QSlider* overrideSlider() const { return override_; }
    QString startBlockedReason() const { return blocked_; }

  signals:
    void enableRequested();
    void homeRequested();
    void startRequested();
    void feedHoldRequested();
    void resumeRequested();
    void abortRequested();
    void resetRequested();
    void emergencyStopRequested();
    void overrideChanged(double fraction);

  protected:
    // Catches the E-STOP key while a modal dialog (file dialog, question) blocks shortcuts.
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void refresh();

    QPushButton* eStop_;
    QPushButton *enable_, *home_, *start_, *hold_, *resume_, *abort_, *reset_;
    QSlider* override_;
    QLabel* overrideLabel_;
    QLabel* reason_;
    QShortcut* eStopShortcut_;
    cutcell::EngineState state_ = cutcell::EngineState::Idle;
    bool homed_ = false;
    QString blocked_;
};

} // namespace CutCell::ui
