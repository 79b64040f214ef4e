#include "ui/panels/control_panel.h"

#include <QApplication>
#include <QGridLayout>
#include <QKeyEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QShortcut>
#include <QSlider>
#include <QVBoxLayout>

namespace CutCell::ui {

using cutcell::EngineState;

ControlPanel::ControlPanel(QWidget* parent)
    : QWidget(parent), eStop_(new QPushButton(this)), override_(new QSlider(Qt::Horizontal, this)),
      overrideLabel_(new QLabel(this)), reason_(new QLabel(this)),
      eStopShortcut_(new QShortcut(QKeySequence(QString::fromLatin1(kEStopKey)), this)) {
    setObjectName("controlPanel");
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(6, 6, 6, 6);

    eStop_->setObjectName("eStopButton");
    eStop_->setText(tr("EMERGENCY\nSTOP  [%1]").arg(kEStopKey));
    eStop_->setToolTip(tr("Torch off and drives disabled at once; latched until Reset. "
                          "Shortcut %1 works from any field.")
                           .arg(kEStopKey));
    eStop_->setMinimumHeight(110);
    eStop_->setFocusPolicy(Qt::NoFocus);
    eStop_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    v->addWidget(eStop_);
    connect(eStop_, &QPushButton::pressed, this, &ControlPanel::emergencyStopRequested);
    eStopShortcut_->setContext(Qt::ApplicationShortcut);
    eStopShortcut_->setAutoRepeat(false);
    connect(eStopShortcut_, &QShortcut::activated, this, &ControlPanel::emergencyStopRequested);
    qApp->installEventFilter(this);

    const auto button = [this](const QString& text, const char* name, auto signal) {
        auto* b = new QPushButton(text, this);
        b->setObjectName(name);
        b->setProperty("operator", true);
        b->setMinimumHeight(48);
        connect(b, &QPushButton::clicked, this, signal);
        return b;
    };
    enable_ = button(tr("Enable"), "enableButton", &ControlPanel::enableRequested);
    home_ = button(tr("Home"), "homeButton", &ControlPanel::homeRequested);
    start_ = button(tr("Start"), "startButton", &ControlPanel::startRequested);
    hold_ = button(tr("Feed hold"), "holdButton", &ControlPanel::feedHoldRequested);
    resume_ = button(tr("Resume"), "resumeButton", &ControlPanel::resumeRequested);
    abort_ = button(tr("Abort"), "abortButton", &ControlPanel::abortRequested);
    reset_ = button(tr("Reset"), "resetButton", &ControlPanel::resetRequested);
    auto* grid = new QGridLayout;
    grid->addWidget(enable_, 0, 0);
    grid->addWidget(home_, 0, 1);
    grid->addWidget(start_, 1, 0, 1, 2);
    grid->addWidget(hold_, 2, 0);
    grid->addWidget(resume_, 2, 1);
    grid->addWidget(abort_, 3, 0);
    grid->addWidget(reset_, 3, 1);
    v->addLayout(grid);

    reason_->setObjectName("startReason");
    reason_->setWordWrap(true);
    reason_->setTextFormat(Qt::PlainText);
    v->addWidget(reason_);

    auto* ovr = new QHBoxLayout;
    auto* ovrTitle = new QLabel(tr("Speed override"), this);
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
        emit overrideChanged(p / 100.0);
    });
    v->addWidget(override_);
    refresh();
}

bool ControlPanel::eventFilter(QObject* watched, QEvent* event) {
    // Shortcuts of the main window are blocked while a modal dialog is open: the key is taken
    // here instead (only then, so it is not handled twice).
    if (event->type() == QEvent::KeyPress && QApplication::activeModalWidget() &&
        watched->isWidgetType()) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (!key->isAutoRepeat() &&
            QKeySequence(key->keyCombination()) == eStopShortcut_->key()) {
            emit emergencyStopRequested();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
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

void ControlPanel::setOverridePercent(int percent) {
    override_->setValue(percent);
}

void ControlPanel::refresh() {
    const bool idle = state_ == EngineState::Idle;
    const bool ready = state_ == EngineState::Ready;
    const bool running = state_ == EngineState::Running;
    const bool paused = state_ == EngineState::Paused;
    const bool latched = state_ == EngineState::EmergencyStop || state_ == EngineState::Fault;
    enable_->setEnabled(idle);
    home_->setEnabled(ready || state_ == EngineState::Completed);
    start_->setEnabled(blocked_.isEmpty());
    hold_->setEnabled(running);
    resume_->setEnabled(paused);
    abort_->setEnabled(running || paused || state_ == EngineState::Homing ||
                       state_ == EngineState::Jogging);
    reset_->setEnabled(latched);
    eStop_->setEnabled(true); // always
    reason_->setVisible(!blocked_.isEmpty());
    reason_->setText(blocked_.isEmpty() ? QString() : tr("Start: %1").arg(blocked_));
    (void)homed_;
}

} // namespace CutCell::ui
