#pragma once
// Enable over a fieldbus. The rig's link (EngineRig::link()) is polled on a GUI timer - a short
// mutex in the rig, never a wait on the bus. Enable with the link down asks the rig to bring it
// up (off the GUI thread) and enables the engine once every node is up; an E-STOP cancels
// that. Every change of the link is re-emitted (bus box, status bar) and its transitions are
// logged with what to do next; the link's own events (node configured, heartbeat lost) go to
// the log as they come.
//
// Threading contract: GUI thread only.
#include "core/engine/engine_types.h"
#include "ui/engine_rig.h"

#include <QObject>

class QTimer;

namespace CutCell::ui {

class LinkControl : public QObject {
    Q_OBJECT
  public:
    static constexpr int kPollMs = 100;

    explicit LinkControl(QObject* parent = nullptr);

    // Null while there is no rig (before the first one, while it is rebuilt).
    void setRig(EngineRig* rig);
    const RigLink& link() const { return link_; }
    bool hasLink() const { return link_.state != RigLink::State::None; }
    bool ready() const;          // no link to bring up, or the link is up
    bool needsReconnect() const; // lost or failed
    bool enablePending() const { return enablePending_; }

    // Enable: true when the engine may be enabled now; false when the link comes up first
    // (enableDue() follows once it is up, enableFailed() if it fails).
    bool requestEnable();
    void cancelEnable();
    void reconnect();
    void poll();

  signals:
    void changed(const CutCell::ui::RigLink& link);
    void enableDue();
    void enableFailed(const QString& why);
    void message(cutcell::Severity severity, const QString& text);

  private:
    void logTransition(RigLink::State from);

    QTimer* timer_;
    EngineRig* rig_ = nullptr;
    RigLink link_;
    bool enablePending_ = false;
};

} // namespace CutCell::ui
