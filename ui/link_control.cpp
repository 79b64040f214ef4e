#include "ui/link_control.h"
#include "ui/panels/engine_text.h"

#include <QTimer>

namespace CutCell::ui {

using cutcell::Severity;
using State = RigLink::State;

LinkControl::LinkControl(QObject* parent) : QObject(parent), timer_(new QTimer(this)) {
    timer_->setInterval(kPollMs);
    connect(timer_, &QTimer::timeout, this, &LinkControl::poll);
}

void LinkControl::setRig(EngineRig* rig) {
    rig_ = rig;
    enablePending_ = false;
    link_ = rig ? rig->link() : RigLink{};
    if (hasLink())
        timer_->start();
    else
        timer_->stop();
    emit changed(link_);
}

bool LinkControl::ready() const {
    return link_.state == State::None || link_.state == State::Up;
}

bool LinkControl::needsReconnect() const {
    return link_.state == State::Lost || link_.state == State::Failed;
}

bool LinkControl::requestEnable() {
    if (!rig_) return false;
    poll(); // decide on the link as it is now
    if (ready()) return true;
    enablePending_ = true;
    if (link_.state != State::Connecting) rig_->connectLink();
    emit message(Severity::Info, tr("Enable: bringing the CAN bus up first (%1); the drives are "
                                    "enabled once every node is operational.")
                                     .arg(QString::fromStdString(link_.where)));
    return false;
}

void LinkControl::cancelEnable() {
    if (!enablePending_) return;
    enablePending_ = false;
    emit message(Severity::Warning,
                 tr("Enable cancelled: the drives stay disabled when the bus comes up."));
}

void LinkControl::reconnect() {
    if (!rig_ || !hasLink()) return;
    if (link_.state == State::Connecting) {
        emit message(Severity::Info, tr("The CAN bus is already being connected."));
        return;
    }
    emit message(Severity::Info,
                 tr("Reconnecting the CAN bus (%1).").arg(QString::fromStdString(link_.where)));
    rig_->reconnectLink();
}

void LinkControl::poll() {
    if (!rig_) return;
    for (const RigLinkEvent& e : rig_->drainLinkEvents())
        emit message(e.error ? Severity::Warning : Severity::Info,
                     engineText(QString::fromStdString(e.text)));
    const RigLink now = rig_->link();
    if (now.changes == link_.changes && now.state == link_.state) return;
    const State from = link_.state;
    link_ = now;
    if (from != link_.state) logTransition(from);
    emit changed(link_);
    if (!enablePending_) return;
    if (link_.state == State::Up) {
        enablePending_ = false;
        emit enableDue();
    } else if (link_.state == State::Failed || link_.state == State::Lost) {
        enablePending_ = false;
        emit enableFailed(engineText(QString::fromStdString(link_.text)));
    }
}

void LinkControl::logTransition(State from) {
    const QString text = engineText(QString::fromStdString(link_.text));
    switch (link_.state) {
    case State::Connecting:
        emit message(Severity::Info, tr("CAN bus: %1").arg(text));
        break;
    case State::Up:
        emit message(Severity::Info, tr("CAN bus %1").arg(text));
        break;
    case State::Failed:
        emit message(Severity::Error,
                     tr("%1. The connection is closed and the port released: check the drives "
                        "and the bus, then press Enable to try again.")
                         .arg(text));
        break;
    case State::Lost:
        emit message(Severity::Error,
                     tr("%1. Drives that were enabled are in Fault. Press Reconnect (bus box) "
                        "or Reset, then Enable.")
                         .arg(text));
        break;
    case State::Down:
        if (from != State::None) emit message(Severity::Info, tr("CAN bus: %1").arg(text));
        break;
    case State::None:
        break;
    }
}

} // namespace CutCell::ui
