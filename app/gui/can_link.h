#pragma once
// The CAN master's connection for the GUI, off the GUI thread. A worker thread ("can-link") is
// the master's only controlling thread: on request it starts the master (connect, listen for
// another master), then polls - bounded - until every node is configured and operational,
// publishing each step; a failure names the plugin, the interface and every node that did not
// come up with its reason, and stops the master again (device closed, port released), so the
// next request starts afresh. While up it watches for a lost bus (connection gone, bus off).
//
// Threading contract: requestUp()/requestReconnect()/status() from any thread; they never wait
// (atomics, a short mutex). The destructor lets the worker run the final action and stop the
// master, and waits for it: at most the connection timeout when a start is in progress.
#include "devices/canopen/canopen_master.h"
#include "ui/engine_rig.h"

#include <functional>
#include <memory>
#include <string>

namespace cutcell::app {

struct CanLinkTiming {
    int connect_timeout_ms = 3000;   // device connected and the bus found free
    int configure_timeout_ms = 5000; // then every node operational
    int poll_ms = 20;
};

class CanLink {
  public:
    // where: "virtualcan can0", for the texts.
    CanLink(canopen::CanOpenMaster& master, std::string where, CanLinkTiming timing = {});
    ~CanLink();
    CanLink(const CanLink&) = delete;
    CanLink& operator=(const CanLink&) = delete;

    // Set before the first request. Runs on the worker when the link ends (destructor), before
    // the master stops; masterRunning: whether the master is started (its bus may be written).
    void setFinalAction(std::function<void(bool masterRunning)> action);
    void requestUp();        // a no-op while up or coming up
    void requestReconnect(); // down (if started), then up
    CutCell::ui::RigLink status() const;

  private:
    class Worker;
    std::unique_ptr<Worker> worker_;
};

} // namespace cutcell::app
