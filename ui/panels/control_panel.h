#pragma once
// The operator's controls: Enable, Home, Start, Feed hold / Resume, Abort, Release E-STOP,
// Reset, the speed override slider and the EMERGENCY STOP. The E-STOP button is never
// disabled and its shortcut (F1, Qt::ApplicationShortcut) works whatever widget has the focus,
// also inside a modal dialog (an application event filter takes the key there). The panel only
// emits requests; RunController decides what is allowed and says why Start is not.
//
// Deliberate stops: Abort asks for a second press within kAbortConfirmMs (the button says so)
// instead of a modal dialog, so E-STOP and Feed hold never wait behind a question. Releasing
// the E-STOP and resetting the latch are two buttons. The override slider shows in amber when
// it is not 100 %.
//
// Threading contract: GUI thread only.
#include "core/engine/engine_types.h"

#include <QWidget>

class QLabel;
class QPushButton;
class QScrollArea;
class QShortcut;
class QSlider;
class QTimer;

namespace CutCell::ui {

class ControlPanel : public QWidget {
    Q_OBJECT
  public:
    static constexpr const char* kEStopKey = "F1";
    static constexpr const char* kEnableKey = "F2";
    static constexpr const char* kHomeKey = "F3";
    static constexpr const char* kResetKey = "F4";
    // Two hands on purpose: releasing the latch is never one stray key next to F1.
    static constexpr const char* kReleaseKey = "Ctrl+Shift+F1";
    static constexpr const char* kStartKey = "F5";
    static constexpr const char* kHoldKey = "F6";
    static constexpr const char* kResumeKey = "F7";
    static constexpr const char* kAbortKey = "F8";
    static constexpr const char* kOverrideDownKey = "F9";
    static constexpr const char* kOverrideUpKey = "F10";
    static constexpr int kAbortConfirmMs = 4000;
    static constexpr int kOverrideStep = 10; // percent per key press
    // The operator's keys and what they do (Help -> Keys).
    static QString keysHelp();

    explicit ControlPanel(QWidget* parent = nullptr);

    // Buttons follow the engine state; Start also needs `startBlocked` to be empty.
    void setState(cutcell::EngineState state, bool homed);
    void setStartBlocked(const QString& reason);
    // Whether the emergency stop request is still pressed (Release E-STOP is offered).
    void setEStopPressed(bool pressed);
    void setOverridePercent(int percent);
    int overridePercent() const;

    QPushButton* eStopButton() const { return eStop_; }
    QPushButton* startButton() const { return start_; }
    QPushButton* enableButton() const { return enable_; }
    QPushButton* homeButton() const { return home_; }
    QPushButton* holdButton() const { return hold_; }
    QPushButton* resumeButton() const { return resume_; }
    QPushButton* abortButton() const { return abort_; }
    QPushButton* releaseButton() const { return release_; }
    QPushButton* resetButton() const { return reset_; }
    QSlider* overrideSlider() const { return override_; }
    QString startBlockedReason() const { return blocked_; }
    bool abortArmed() const;

  signals:
    void enableRequested();
    void homeRequested();
    void startRequested();
    void feedHoldRequested();
    void resumeRequested();
    void abortRequested(); // only after the confirming second press
    void releaseEStopRequested();
    void resetRequested();
    void emergencyStopRequested();
    void overrideChanged(double fraction);

  protected:
    // Catches the E-STOP key while a modal dialog (file dialog, question) blocks shortcuts.
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void refresh();
    void onAbortPressed();
    void addShortcut(const char* key, QPushButton* button, void (ControlPanel::*slot)());
    void stepOverride(int delta);

    QPushButton* eStop_;
    QPushButton *enable_, *home_, *start_, *hold_, *resume_, *abort_, *release_, *reset_;
    QSlider* override_;
    QLabel* overrideLabel_;
    QLabel* reason_;
    QScrollArea* reasonBox_;
    QShortcut* eStopShortcut_;
    QTimer* abortArm_;
    cutcell::EngineState state_ = cutcell::EngineState::Idle;
    bool homed_ = false;
    bool estopPressed_ = false;
    QString blocked_;
};

} // namespace CutCell::ui
