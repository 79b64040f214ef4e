#include "ui/panels/control_panel.h"

#include <QApplication>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QShortcut>
#include <QSlider>
#include <QStyle>
#include <QTimer>
#include <QVBoxLayout>

namespace CutCell::ui {

using cutcell::EngineState;

namespace {
void repolish(QWidget* w) {
    w->style()->unpolish(w);
    w->style()->polish(w);
}
} // namespace

QString ControlPanel::keysHelp() {
    const auto key = [](const char* k) { return QString::fromLatin1(k); };
    return tr("%1: EMERGENCY STOP (works from any field, also in dialogs)\n"
              "%2: Enable\n%3: Home\n%4: Reset\n%5: Release E-STOP\n")
               .arg(key(kEStopKey), key(kEnableKey), key(kHomeKey), key(kResetKey),
                    key(kReleaseKey)) +
           tr("%1: Start\n%2: Feed hold\n%3: Resume\n%4: Abort (press twice within %5 s)\n")
               .arg(key(kStartKey), key(kHoldKey), key(kResumeKey), key(kAbortKey))
               .arg(kAbortConfirmMs / 1000) +
           tr("%1 / %2: speed override -%3 % / +%3 %\nF12: acknowledge the alarms\nCtrl+N / Ctrl+O "
              "/ Ctrl+S: job files")
               .arg(key(kOverrideDownKey), key(kOverrideUpKey))
               .arg(kOverrideStep);
}

ControlPanel::ControlPanel(QWidget* parent)
    : QWidget(parent), eStop_(new QPushButton(this)), override_(new QSlider(Qt::Horizontal, this)),
      overrideLabel_(new QLabel(this)), reason_(new QLabel), reasonBox_(new QScrollArea(this)),
      eStopShortcut_(new QShortcut(QKeySequence(QString::fromLatin1(kEStopKey)), this)),
      abortArm_(new QTimer(this)) {
    setObjectName("controlPanel");
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(6, 6, 6, 6);

    eStop_->setObjectName("eStopButton");
    eStop_->setText(tr("EMERGENCY\nSTOP  [%1]").arg(kEStopKey));
    eStop_->setToolTip(tr("Torch off and drives disabled at once; latched until released and "
                          "Reset. Shortcut %1 works from any field.")
                           .arg(kEStopKey));
    eStop_->setMinimumHeight(96);
    eStop_->setFocusPolicy(Qt::NoFocus);
    eStop_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    v->addWidget(eStop_);
    connect(eStop_, &QPushButton::pressed, this, &ControlPanel::emergencyStopRequested);
    eStopShortcut_->setContext(Qt::ApplicationShortcut);
    eStopShortcut_->setAutoRepeat(false);
    connect(eStopShortcut_, &QShortcut::activated, this, &ControlPanel::emergencyStopRequested);
    qApp->installEventFilter(this);

    const auto button = [this](const QString& text, const char* name, const char* key) {
        auto* b = new QPushButton(
            key ? QStringLiteral("%1  [%2]").arg(text, QLatin1String(key)) : text, this);
        b->setObjectName(name);
        b->setProperty("operator", true);
        b->setMinimumHeight(44);
        b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        return b;
    };
    enable_ = button(tr("Enable"), "enableButton", nullptr);
    home_ = button(tr("Home"), "homeButton", nullptr);
    start_ = button(tr("Start"), "startButton", kStartKey);
    // Half-width buttons carry their key in the tooltip (the text would not fit at 13 pt).
    hold_ = button(tr("Feed hold"), "holdButton", nullptr);
    resume_ = button(tr("Resume"), "resumeButton", nullptr);
    hold_->setToolTip(tr("Decelerates along the path and holds there [%1]").arg(kHoldKey));
    resume_->setToolTip(tr("Continues the cut from where it held [%1]").arg(kResumeKey));
    abort_ = button(tr("Abort"), "abortButton", kAbortKey);
    release_ = button(tr("Release\nE-STOP"), "releaseButton", nullptr);
    reset_ = button(tr("Reset"), "resetButton", nullptr);
    abort_->setToolTip(tr("Stops the cut along the path with the torch off. Press twice: the "
                          "first press asks, the second (within %1 s) aborts.")
                           .arg(kAbortConfirmMs / 1000));
    release_->setToolTip(tr("The emergency stop button was pulled back out (the hazard is "
                            "gone). Reset then clears the latch [%1].")
                             .arg(QLatin1String(kReleaseKey)));
    reset_->setToolTip(tr("Clears a fault, or an emergency stop once it is released [%1].")
                           .arg(QLatin1String(kResetKey)));
    enable_->setToolTip(
        tr("Enables the drives (and connects the CAN bus) [%1]").arg(QLatin1String(kEnableKey)));
    home_->setToolTip(tr("Moves every axis to its reference at the job's home speed [%1]")
                          .arg(QLatin1String(kHomeKey)));
    connect(enable_, &QPushButton::clicked, this, &ControlPanel::enableRequested);
    connect(home_, &QPushButton::clicked, this, &ControlPanel::homeRequested);
    connect(start_, &QPushButton::clicked, this, &ControlPanel::startRequested);
    connect(hold_, &QPushButton::clicked, this, &ControlPanel::feedHoldRequested);
    connect(resume_, &QPushButton::clicked, this, &ControlPanel::resumeRequested);
    connect(abort_, &QPushButton::clicked, this, &ControlPanel::onAbortPressed);
    connect(release_, &QPushButton::clicked, this, &ControlPanel::releaseEStopRequested);
    connect(reset_, &QPushButton::clicked, this, &ControlPanel::resetRequested);
    auto* grid = new QGridLayout;
    grid->addWidget(enable_, 0, 0);
    grid->addWidget(home_, 0, 1);
    grid->addWidget(start_, 1, 0, 1, 2);
    grid->addWidget(hold_, 2, 0);
    grid->addWidget(resume_, 2, 1);
    grid->addWidget(abort_, 3, 0, 1, 2);
    grid->addWidget(release_, 4, 0);
    grid->addWidget(reset_, 4, 1);
    v->addLayout(grid);

    abortArm_->setSingleShot(true);
    abortArm_->setInterval(kAbortConfirmMs);
    connect(abortArm_, &QTimer::timeout, this, &ControlPanel::refresh);

    // The Start reason has a fixed place (three lines, scrolling beyond, the whole text in the
    // tooltip): a long reason never pushes the slider and the lamps around.
    reason_->setObjectName("startReason");
    reason_->setWordWrap(true);
    reason_->setTextFormat(Qt::PlainText);
    reason_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    reasonBox_->setObjectName("startReasonBox");
    reasonBox_->setWidget(reason_);
    reasonBox_->setWidgetResizable(true);
    reasonBox_->setFrameShape(QFrame::NoFrame);
    reasonBox_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    reasonBox_->setFixedHeight(3 * 19 + 14); // three lines of the reason's 11 pt type + padding
    v->addWidget(reasonBox_);

    auto* ovr = new QHBoxLayout;
    auto* ovrTitle =
        new QLabel(tr("Speed override [%1 -, %2 +]")
                       .arg(QLatin1String(kOverrideDownKey), QLatin1String(kOverrideUpKey)),
                   this);
    ovr->addWidget(ovrTitle);
    ovr->addStretch(1);
    overrideLabel_->setObjectName("overrideValue");
    ovr->addWidget(overrideLabel_);
    v->addLayout(ovr);
    override_->setObjectName("overrideSlider");
    override_->setRange(10, 150);
    override_->setSingleStep(5);
    override_->setPageStep(10);
    override_->setTickInterval(10);
    override_->setTickPosition(QSlider::TicksBelow);
    override_->setValue(100);
    overrideLabel_->setText(QStringLiteral("100 %"));
    connect(override_, &QSlider::valueChanged, this, [this](int p) {
        overrideLabel_->setText(QStringLiteral("%1 %").arg(p));
        // Amber while not 100 %: the operator sees that the machine runs off its nominal speed.
        if (overrideLabel_->property("offNominal").toBool() != (p != 100)) {
            overrideLabel_->setProperty("offNominal", p != 100);
            repolish(overrideLabel_);
        }
        emit overrideChanged(p / 100.0);
    });
    v->addWidget(override_);

    addShortcut(kEnableKey, enable_, &ControlPanel::enableRequested);
    addShortcut(kHomeKey, home_, &ControlPanel::homeRequested);
    addShortcut(kResetKey, reset_, &ControlPanel::resetRequested);
    addShortcut(kReleaseKey, release_, &ControlPanel::releaseEStopRequested);
    addShortcut(kStartKey, start_, &ControlPanel::startRequested);
    addShortcut(kHoldKey, hold_, &ControlPanel::feedHoldRequested);
    addShortcut(kResumeKey, resume_, &ControlPanel::resumeRequested);
    addShortcut(kAbortKey, abort_, &ControlPanel::onAbortPressed);
    auto* down = new QShortcut(QKeySequence(QString::fromLatin1(kOverrideDownKey)), this);
    down->setContext(Qt::ApplicationShortcut);
    connect(down, &QShortcut::activated, this, [this] { stepOverride(-kOverrideStep); });
    auto* up = new QShortcut(QKeySequence(QString::fromLatin1(kOverrideUpKey)), this);
    up->setContext(Qt::ApplicationShortcut);
    connect(up, &QShortcut::activated, this, [this] { stepOverride(kOverrideStep); });
    refresh();
}

void ControlPanel::addShortcut(const char* key, QPushButton* button, void (ControlPanel::*slot)()) {
    auto* s = new QShortcut(QKeySequence(QString::fromLatin1(key)), this);
    s->setContext(Qt::ApplicationShortcut);
    s->setAutoRepeat(false);
    // A key acts like its button: only when the button is enabled.
    connect(s, &QShortcut::activated, this, [this, button, slot] {
        if (button->isEnabled()) (this->*slot)();
    });
}

void ControlPanel::stepOverride(int delta) {
    override_->setValue(override_->value() + delta);
}

bool ControlPanel::eventFilter(QObject* watched, QEvent* event) {
    // Shortcuts of the main window are blocked while a modal dialog is open: the key is taken
    // here instead (only then, so it is not handled twice).
    if (event->type() == QEvent::KeyPress && QApplication::activeModalWidget() &&
        watched->isWidgetType()) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (!key->isAutoRepeat() && QKeySequence(key->keyCombination()) == eStopShortcut_->key()) {
            emit emergencyStopRequested();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void ControlPanel::onAbortPressed() {
    if (!abort_->isEnabled()) return;
    if (abortArm_->isActive()) {
        abortArm_->stop();
        refresh();
        emit abortRequested();
        return;
    }
    abortArm_->start();
    refresh();
}

bool ControlPanel::abortArmed() const {
    return abortArm_->isActive();
}

void ControlPanel::setState(EngineState state, bool homed) {
    state_ = state;
    homed_ = homed;
    refresh();
}

void ControlPanel::setStartBlocked(const QString& reason) {
    blocked_ = reason;
    refresh();
}

void ControlPanel::setEStopPressed(bool pressed) {
    estopPressed_ = pressed;
    refresh();
}

void ControlPanel::setOverridePercent(int percent) {
    override_->setValue(percent);
}

int ControlPanel::overridePercent() const {
    return override_->value();
}

void ControlPanel::refresh() {
    const bool idle = state_ == EngineState::Idle;
    const bool ready = state_ == EngineState::Ready;
    const bool running = state_ == EngineState::Running;
    const bool paused = state_ == EngineState::Paused;
    const bool estop = state_ == EngineState::EmergencyStop;
    const bool latched = estop || state_ == EngineState::Fault;
    enable_->setEnabled(idle && !estopPressed_);
    home_->setEnabled(ready || state_ == EngineState::Completed);
    start_->setEnabled(blocked_.isEmpty() && !estopPressed_);
    hold_->setEnabled(running);
    resume_->setEnabled(paused);
    const bool abortable =
        running || paused || state_ == EngineState::Homing || state_ == EngineState::Jogging;
    if (!abortable) abortArm_->stop();
    abort_->setEnabled(abortable);
    abort_->setText(abortArm_->isActive() ? tr("Press again to ABORT  [%1]").arg(kAbortKey)
                                          : tr("Abort  [%1]").arg(kAbortKey));
    if (abort_->property("armed").toBool() != abortArm_->isActive()) {
        abort_->setProperty("armed", abortArm_->isActive());
        repolish(abort_);
    }
    release_->setEnabled(estopPressed_);
    // An emergency stop is reset only after it was released: two deliberate actions.
    reset_->setEnabled(latched && !(estop && estopPressed_));
    eStop_->setEnabled(true); // always
    QString text;
    if (estopPressed_)
        text = tr("E-STOP pressed: remove the hazard, then Release E-STOP and Reset.");
    else if (!blocked_.isEmpty())
        text = tr("Start: %1").arg(blocked_);
    reason_->setText(text);
    reasonBox_->setToolTip(text);
    reason_->setToolTip(text);
    (void)homed_;
}

} // namespace CutCell::ui
