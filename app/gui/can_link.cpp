#include "can_link.h"

#include "core/common/c_format.h"

#include <QThread>
#include <QTimer>

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>

namespace cutcell::app {

using CutCell::ui::RigLink;
using State = RigLink::State;
using namespace cutcell::canopen;

namespace {

std::int64_t nowMs() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

bool busGone(BusState b) {
    return b == BusState::Disconnected || b == BusState::BusOff;
}

bool nodeUp(const CanNodeSnapshot& n) {
    return n.configured && n.nmt == NmtState::Operational;
}

// "nodes 1, 2, 5: no boot-up within 1000 ms ...; node 3: SDO 0x6060:00 unanswered ..."
std::string nodesNotUp(const CanBusSnapshot& s) {
    std::map<std::string, std::string> byReason; // reason -> "1, 2, 5"
    std::map<std::string, int> count;
    for (const CanNodeSnapshot& n : s.nodes) {
        if (nodeUp(n)) continue;
        const std::string why = n.fault_text.empty() ? messageC("no answer") : n.fault_text;
        std::string& ids = byReason[why];
        ids += (ids.empty() ? "" : ", ") + std::to_string(n.node);
        ++count[why];
    }
    std::string out;
    for (const auto& [why, ids] : byReason)
        out += (out.empty() ? "" : "; ") +
               messageC(count[why] > 1 ? "nodes %s: %s" : "node %s: %s", ids.c_str(), why.c_str());
    return out;
}

} // namespace

class CanLink::Worker {
  public:
    Worker(CanOpenMaster& master, std::string where, CanLinkTiming timing)
        : master_(master), where_(std::move(where)), timing_(timing) {
        status_.state = State::Down;
        status_.where = where_;
        status_.nodes = master_.driveCount();
        status_.text = messageC("not connected (%s)", where_.c_str());
        thread_.setObjectName(QStringLiteral("can-link"));
        context_ = new QObject;
        context_->moveToThread(&thread_);
        thread_.start();
        QMetaObject::invokeMethod(
            context_,
            [this] {
                timer_ = new QTimer(context_);
                QObject::connect(timer_, &QTimer::timeout, context_, [this] { tick(); });
                timer_->start(timing_.poll_ms);
            },
            Qt::QueuedConnection);
    }

    ~Worker() {
        shutdown_.store(true, std::memory_order_release);
        thread_.wait(); // the worker quits its loop after the final action (tick)
        delete context_;
    }

    std::function<void(bool)> finalAction;
    std::atomic<std::uint32_t> upRequests{0};
    std::atomic<std::uint32_t> reconnectRequests{0};

    RigLink status() const {
        std::lock_guard lock(mutex_);
        return status_;
    }

  private:
    void publish(State s, const std::string& text, int ready) {
        std::lock_guard lock(mutex_);
        if (status_.state == s && status_.text == text && status_.nodes_ready == ready) return;
        status_.state = s;
        status_.text = text;
        status_.nodes_ready = ready;
        ++status_.changes;
    }

    // Every poll; re-entered from inside master.start() (it runs this thread's events while
    // it waits for the connection): then it only returns.
    void tick() {
        if (inStart_) return;
        if (shutdown_.load(std::memory_order_acquire)) {
            if (finalAction) finalAction(started_);
            master_.stop();
            started_ = false;
            timer_->stop();
            thread_.quit();
            return;
        }
        const std::uint32_t reconnect = reconnectRequests.load(std::memory_order_acquire);
        const std::uint32_t up = upRequests.load(std::memory_order_acquire);
        const bool wantReconnect = reconnect != seenReconnect_;
        const bool wantUp = wantReconnect || up != seenUp_;
        seenReconnect_ = reconnect;
        seenUp_ = up;
        if (wantReconnect && (phase_ == State::Up || phase_ == State::Connecting)) takeDown();
        switch (phase_) {
        case State::Down:
        case State::Failed:
        case State::Lost:
            if (wantUp) bringUp();
            break;
        case State::Connecting:
            superviseConfiguring();
            break;
        case State::Up:
            superviseUp();
            break;
        case State::None:
            break;
        }
    }

    void takeDown() {
        master_.stop();
        started_ = false;
        phase_ = State::Down;
        publish(State::Down, messageC("disconnected from %s", where_.c_str()), 0);
    }

    void bringUp() {
        if (started_) master_.stop(); // after a loss: the old device goes, the port with it
        started_ = false;
        phase_ = State::Connecting;
        publish(State::Connecting,
                messageC("connecting to %s (listening for another master)", where_.c_str()), 0);
        std::string why;
        inStart_ = true;
        const bool ok = master_.start(&why, timing_.connect_timeout_ms); // stops itself on failure
        inStart_ = false;
        if (!ok) {
            phase_ = State::Failed;
            publish(State::Failed, messageC("CAN bus %s: %s", where_.c_str(), why.c_str()), 0);
            return;
        }
        started_ = true;
        deadlineMs_ = nowMs() + timing_.configure_timeout_ms;
        settleUntilMs_ = 0;
        publish(State::Connecting,
                messageC("connected to %s; configuring the nodes", where_.c_str()), 0);
    }

    void superviseConfiguring() {
        const CanBusSnapshot s = master_.snapshot();
        int ready = 0, failed = 0;
        for (const CanNodeSnapshot& n : s.nodes) {
            if (nodeUp(n))
                ++ready;
            else if (!n.fault_text.empty())
                ++failed;
        }
        const int count = static_cast<int>(s.nodes.size());
        if (busGone(s.bus))
            return fail(messageC("the bus went away while configuring (%s)", s.bus_text.c_str()));
        if (ready == count && master_.allOperational()) {
            // Operational is not yet "ready to enable": a drive still in Fault from before
            // (a bus lost while enabled) gets the fault reset the engine asked for in its first
            // cycles. Wait for every drive's state, a moment at most, so an Enable right away
            // does not meet that Fault.
            bool settled = true;
            for (const CanNodeSnapshot& n : s.nodes)
                settled = settled && n.state != Cia402State::Unknown &&
                          n.state != Cia402State::Fault &&
                          n.state != Cia402State::FaultReactionActive;
            if (!settled && settleUntilMs_ == 0) settleUntilMs_ = nowMs() + kSettleMs;
            if (!settled && nowMs() < settleUntilMs_) {
                publish(State::Connecting,
                        messageC("every node operational on %s; reading the drives' states",
                                 where_.c_str()),
                        ready);
                return;
            }
            phase_ = State::Up;
            publish(State::Up, messageC("up on %s: %d nodes operational", where_.c_str(), count),
                    ready);
            return;
        }
        if (ready + failed == count || nowMs() > deadlineMs_) {
            const std::string notUp = nodesNotUp(s);
            return fail(ready + failed == count
                            ? messageC("%d of %d nodes did not come up: %s", count - ready, count,
                                       notUp.c_str())
                            : messageC("%d of %d nodes did not come up (within %d ms): %s",
                                       count - ready, count, timing_.configure_timeout_ms,
                                       notUp.c_str()));
        }
        publish(State::Connecting,
                messageC("configuring the nodes on %s: %d of %d operational", where_.c_str(), ready,
                         count),
                ready);
    }

    void superviseUp() {
        const CanBusSnapshot s = master_.snapshot();
        int ready = 0;
        for (const CanNodeSnapshot& n : s.nodes)
            ready += nodeUp(n) ? 1 : 0;
        if (busGone(s.bus)) {
            phase_ = State::Lost;
            publish(State::Lost,
                    messageC("CAN bus lost on %s: %s", where_.c_str(), s.bus_text.c_str()), 0);
            return;
        }
        const int count = static_cast<int>(s.nodes.size());
        publish(State::Up,
                ready == count ? messageC("up on %s: %d nodes operational", where_.c_str(), count)
                               : messageC("up on %s; %d node(s) not operational: %s",
                                          where_.c_str(), count - ready, nodesNotUp(s).c_str()),
                ready);
    }

    // The attempt ends: the master stops (device closed, port released), the reason stays.
    void fail(const std::string& why) {
        master_.stop();
        started_ = false;
        phase_ = State::Failed;
        publish(State::Failed, messageC("CAN bus %s: %s", where_.c_str(), why.c_str()), 0);
    }

    CanOpenMaster& master_;
    const std::string where_;
    const CanLinkTiming timing_;
    QThread thread_;
    QObject* context_ = nullptr;
    QTimer* timer_ = nullptr; // on the worker thread
    std::atomic<bool> shutdown_{false};
    // Worker thread only.
    State phase_ = State::Down;
    bool started_ = false;
    bool inStart_ = false;
    std::uint32_t seenUp_ = 0, seenReconnect_ = 0;
    std::int64_t deadlineMs_ = 0;
    std::int64_t settleUntilMs_ = 0; // 0: not waiting for the drives' states
    static constexpr std::int64_t kSettleMs = 300;
    mutable std::mutex mutex_;
    RigLink status_;
};

CanLink::CanLink(CanOpenMaster& master, std::string where, CanLinkTiming timing)
    : worker_(std::make_unique<Worker>(master, std::move(where), timing)) {}

CanLink::~CanLink() = default;

void CanLink::setFinalAction(std::function<void(bool)> action) {
    worker_->finalAction = std::move(action);
}

void CanLink::requestUp() {
    worker_->upRequests.fetch_add(1, std::memory_order_acq_rel);
}

void CanLink::requestReconnect() {
    worker_->reconnectRequests.fetch_add(1, std::memory_order_acq_rel);
}

RigLink CanLink::status() const {
    return worker_->status();
}

} // namespace cutcell::app
