// The CANopen master's lifecycle and its thread-safe face; the bus work is in master_io.cpp.
//
// Why SYNC comes from a pacing thread (or the engine) and not from a QTimer: QTimer has whole
// millisecond intervals in Qt 6.4 and fires late by the event loop's load; a thread sleeping
// to absolute deadlines (clock_nanosleep) keeps the period and only the hand-over to the
// master thread (eventfd -> QSocketNotifier) adds jitter. stats() reports the jitter measured
// at the moment each SYNC is written, which is what the drives see.
#include "devices/canopen/canopen_master.h"
#include "core/common/c_format.h"
#include "devices/canopen/thread_priority.h"

#include "core/job/job.h"
#include "devices/canopen/bus_load.h"
#include "devices/canopen/can_interface.h"
#include "devices/canopen/master_impl.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QLoggingCategory>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <sys/eventfd.h>
#include <thread>
#include <unistd.h>

Q_LOGGING_CATEGORY(lcCanOpen, "cutcell.canopen")

namespace cutcell::canopen {

std::int64_t steadyNs() {
    return std::chrono::steady_clock::now().time_since_epoch().count();
}

CanOpenMasterConfig masterConfigFromJob(const Job& job, double period_s, int axisCount) {
    CanOpenMasterConfig c;
    c.plugin = QString::fromStdString(job.devices.can_plugin);
    c.interface = QString::fromStdString(job.devices.can_interface);
    c.bitrate_bps = job.devices.bitrate_bps;
    c.period_s = period_s;
    c.heartbeat_timeout_s = job.devices.heartbeat_timeout_ms * 1e-3;
    c.sync_counter_overflow = job.devices.sync_counter_overflow;
    for (int a = 0; a < axisCount && a < kMaxAxes; ++a)
        c.nodes.push_back({job.devices.node_ids[static_cast<size_t>(a)],
                           job.devices.counts_per_unit[static_cast<size_t>(a)], false});
    return c;
}

CanOpenMaster::CanOpenMaster(CanOpenMasterConfig config) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.cfg = std::move(config);
    m.wakeFd = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
    m.syncFd = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
    m.rt.resize(m.cfg.nodes.size());
    m.faultText.resize(m.cfg.nodes.size());
    m.emcyText.resize(m.cfg.nodes.size());
    size_t lastDrive = m.cfg.nodes.size();
    for (size_t i = 0; i < m.cfg.nodes.size(); ++i)
        if (!m.cfg.nodes[i].encoder) lastDrive = i;
    for (size_t i = 0; i < m.cfg.nodes.size(); ++i) {
        const MasterNodeConfig& n = m.cfg.nodes[i];
        m.shared.emplace_back();
        if (n.encoder) {
            m.encoders.push_back(
                std::make_unique<CanOpenEncoder>(n.node, n.counts_per_unit, m.shared.back()));
            m.countsPerAxisUnit.push_back(n.counts_per_unit);
            continue;
        }
        const bool last = i == lastDrive;
        m.drives.push_back(std::make_unique<CanOpenDrive>(
            n.node, n.counts_per_unit, n.linear, m.shared.back(), m.wakeFd,
            last && m.cfg.sync == SyncSource::LastDriveWrite ? m.syncFd : -1, n.mode));
        m.countsPerAxisUnit.push_back(m.drives.back()->countsPerAxisUnit());
    }
    // Encoders answer the SYNCs the last drive's writes post: dated by that drive's cycles.
    m.clockNode = lastDrive;
    if (lastDrive < m.cfg.nodes.size())
        for (auto& e : m.encoders)
            e->setCycleClock(&m.shared[lastDrive].write_seq);
    m.pdoTimeoutNs =
        std::max<std::int64_t>(100'000'000, static_cast<std::int64_t>(10 * m.cfg.period_s * 1e9));
    m.heartbeatTimeoutNs = static_cast<std::int64_t>(m.cfg.heartbeat_timeout_s * 1e9);
    m.heartbeatProducerMs =
        static_cast<std::uint16_t>(std::max(10.0, m.cfg.heartbeat_timeout_s * 1e3 / 3));
    BusLoadInput in;
    in.period_s = m.cfg.period_s;
    in.bitrate_bps = m.cfg.bitrate_bps;
    in.nodes = static_cast<int>(m.cfg.nodes.size());
    in.rpdo_bytes = kRpdo1Bytes;
    in.tpdo_bytes = kTpdo1Bytes;
    in.heartbeat_period_s = m.heartbeatProducerMs * 1e-3;
    in.other_heartbeats = m.cfg.master_node_id > 0 ? 1 : 0; // the master's own
    in.limit = m.cfg.bus_load_limit;
    const BusLoad load = computeBusLoad(in);
    m.load = load.load;
    m.loadText = load.message;
}

CanOpenMaster::~CanOpenMaster() {
    stop();
    ::close(impl_->wakeFd);
    ::close(impl_->syncFd);
}

bool CanOpenMaster::start(std::string* error, int timeout_ms) {
    Impl& m = *impl_;
    auto fail = [&](const std::string& why) {
        if (error) *error = why;
        return false;
    };
    if (m.thread) return true;
    if (m.wakeFd < 0 || m.syncFd < 0)
        return fail(messageC("cannot create eventfd for the CAN master"));
    if (std::string why; !checkConfig(&why)) return fail(why);
    // A new connection: nothing of the previous one's nodes stands (the master thread is not
    // running, the engine only reads these atomics).
    m.stopping = false;
    for (size_t i = 0; i < m.shared.size(); ++i) {
        NodeShared& s = m.shared[i];
        s.configured = false;
        s.master_fault.store(0, std::memory_order_release);
        s.last_emcy.store(0, std::memory_order_release);
        s.nmt.store(static_cast<std::uint8_t>(NmtState::Unknown), std::memory_order_release);
        s.statusword.store(0, std::memory_order_release);
        s.tpdo_count.store(0, std::memory_order_release);
        // The start-up phases begin again; a fault reset the engine asked for while the bus
        // was down (seen_resets behind the counter) is still sent once the node runs.
        const std::uint32_t seenResets = m.rt[i].seen_resets;
        m.rt[i] = NodeRuntime{};
        m.rt[i].seen_resets = seenResets;
        m.rt[i].cleared_resets = s.fault_reset_requests.load(std::memory_order_acquire);
        std::lock_guard lock(m.mutex);
        m.faultText[i].clear();
        m.emcyText[i].clear();
    }
    m.thread = std::make_unique<QThread>();
    m.thread->setObjectName(QStringLiteral("canopen-master"));
    m.context = new QObject;
    m.context->moveToThread(m.thread.get());
    m.thread->start(QThread::TimeCriticalPriority);
    QMetaObject::invokeMethod(
        m.context,
        [&m] {
            raiseCallingThreadToFifo(kMasterThreadPriority); // best effort (thread_priority.h)
            m.openDevice();
        },
        Qt::QueuedConnection);
    // Wait for the connection and the listening. This thread may host the virtualcan bus (its
    // first client lives here, e.g. a GUI or a test): keep its events flowing meanwhile, or
    // nothing moves on the bus and the listening hears a silent bus.
    const bool hasEventLoop = QThread::currentThread()->eventDispatcher() != nullptr;
    const auto until = std::chrono::steady_clock::now() +
                       std::chrono::milliseconds(timeout_ms + m.cfg.listen_before_start_ms);
    std::unique_lock lock(m.mutex);
    while (!(m.taken || m.connectFailed) && std::chrono::steady_clock::now() < until) {
        m.changed.wait_for(lock, std::chrono::milliseconds(2));
        if (hasEventLoop) {
            lock.unlock();
            QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents, 2);
            lock.lock();
        }
    }
    const bool ok = m.taken;
    std::string why = m.connectFailed
                          ? m.connectError
                          : messageC("CAN connection to %s %s did not come up within %d ms",
                                     m.cfg.plugin.toStdString().c_str(),
                                     m.cfg.interface.toStdString().c_str(), timeout_ms);
    lock.unlock();
    if (!ok) {
        stop();
        return fail(why);
    }
    if (m.cfg.sync == SyncSource::Internal) {
        m.pacing = true;
        m.pacer = std::thread([&m] {
            const auto period = static_cast<std::int64_t>(m.cfg.period_s * 1e9);
            timespec next{};
            clock_gettime(CLOCK_MONOTONIC, &next);
            while (m.pacing.load(std::memory_order_relaxed)) {
                next.tv_nsec += period;
                while (next.tv_nsec >= 1'000'000'000) {
                    next.tv_nsec -= 1'000'000'000;
                    ++next.tv_sec;
                }
                clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr);
                postEventFd(m.syncFd);
            }
        });
    }
    return true;
}

bool CanOpenMaster::checkConfig(std::string* error) const {
    const Impl& m = *impl_;
    std::string why;
    if (m.cfg.nodes.empty())
        why = messageC("no CAN nodes configured");
    else if (m.load > m.cfg.bus_load_limit)
        why = messageC("CAN bus load too high: %s", m.loadText.c_str());
    else if (checkCanInterface(m.cfg.plugin, m.cfg.interface, &why))
        return true;
    if (error) *error = why;
    return false;
}

void CanOpenMaster::stop() {
    Impl& m = *impl_;
    if (m.pacer.joinable()) {
        m.pacing = false;
        m.pacer.join();
    }
    if (!m.thread) return;
    QMetaObject::invokeMethod(
        m.context,
        [&m] {
            m.closeDevice();
            // Timers and notifiers die on their own thread.
            delete m.housekeeping;
            delete m.wakeNotifier;
            delete m.syncNotifier;
            m.housekeeping = nullptr;
            m.wakeNotifier = m.syncNotifier = nullptr;
        },
        Qt::BlockingQueuedConnection);
    m.thread->quit();
    m.thread->wait();
    delete m.context;
    m.context = nullptr;
    m.thread.reset();
    std::lock_guard lock(m.mutex);
    m.connected = m.connectFailed = m.taken = false;
}

bool CanOpenMaster::disableAllNow(int timeout_ms) {
    Impl& m = *impl_;
    for (NodeShared& s : m.shared)
        s.goal.store(static_cast<std::uint8_t>(DriveGoal::Disabled), std::memory_order_release);
    if (!m.context) return false;
    // The queued call may outlive this wait (master thread busy): it owns its flag.
    auto done = std::make_shared<std::atomic<bool>>(false);
    QMetaObject::invokeMethod(
        m.context,
        [&m, done] {
            m.writeDisableAll();
            done->store(true, std::memory_order_release);
        },
        Qt::QueuedConnection);
    const std::int64_t until = steadyNs() + static_cast<std::int64_t>(timeout_ms) * 1'000'000;
    while (!done->load(std::memory_order_acquire) && steadyNs() < until)
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    return done->load(std::memory_order_acquire);
}

void CanOpenMaster::setEventSink(std::function<void(const MasterEvent&)> sink) {
    impl_->sink = std::move(sink);
}

int CanOpenMaster::driveCount() const {
    return static_cast<int>(impl_->drives.size());
}
CanOpenDrive* CanOpenMaster::drive(int i) {
    return impl_->drives.at(static_cast<size_t>(i)).get();
}
int CanOpenMaster::encoderCount() const {
    return static_cast<int>(impl_->encoders.size());
}
CanOpenEncoder* CanOpenMaster::encoder(int i) {
    return impl_->encoders.at(static_cast<size_t>(i)).get();
}

bool CanOpenMaster::allOperational() const {
    for (const NodeShared& s : impl_->shared)
        if (!s.configured.load() || static_cast<NmtState>(s.nmt.load()) != NmtState::Operational)
            return false;
    return true;
}

void CanOpenMaster::sync() {
    postEventFd(impl_->syncFd);
}

std::uint64_t CanOpenMaster::cyclesSent() const {
    return impl_->cycles.load(std::memory_order_acquire);
}
std::uint64_t CanOpenMaster::cyclesCompleted() const {
    return impl_->completed.load(std::memory_order_acquire);
}

void CanOpenMaster::emergencyStop(bool disableVoltage) {
    const auto goal =
        static_cast<std::uint8_t>(disableVoltage ? DriveGoal::Disabled : DriveGoal::QuickStop);
    for (NodeShared& s : impl_->shared) {
        s.goal.store(goal, std::memory_order_release);
        s.urgent.store(true, std::memory_order_release);
    }
    postEventFd(impl_->wakeFd);
}

void CanOpenMaster::recoverBus() {
    Impl& m = *impl_;
    if (!m.context) return;
    QMetaObject::invokeMethod(
        m.context,
        [&m] {
            m.event(0, false,
                    messageC("recovering the bus: reconnecting and configuring the nodes again"));
            m.closeDevice();
            m.stopping = false;
            m.openDevice();
        },
        Qt::QueuedConnection);
}

CanBusSnapshot CanOpenMaster::snapshot() const {
    const Impl& m = *impl_;
    CanBusSnapshot s;
    const std::int64_t now = steadyNs();
    std::lock_guard lock(m.mutex);
    s.bus = m.bus;
    s.bus_text = m.busText;
    s.load = m.load;
    s.load_text = m.loadText;
    for (size_t i = 0; i < m.shared.size(); ++i) {
        const NodeShared& n = m.shared[i];
        CanNodeSnapshot c;
        c.node = m.cfg.nodes[i].node;
        c.nmt = static_cast<NmtState>(n.nmt.load());
        c.statusword = n.statusword.load();
        c.configured = n.configured.load();
        c.state = n.tpdo_count.load() > 0 ? decodeStatusword(c.statusword) : Cia402State::Unknown;
        c.position = n.actual_counts.load() / m.countsPerAxisUnit[i];
        const std::int64_t hb = n.heartbeat_ns.load();
        c.heartbeat_age_ms = hb == 0 ? -1 : static_cast<double>(now - hb) * 1e-6;
        c.last_emcy_code = n.last_emcy.load();
        c.last_emcy_text = m.emcyText[i];
        c.fault_code = n.master_fault.load();
        c.fault_text = m.faultText[i];
        s.nodes.push_back(std::move(c));
    }
    return s;
}

std::vector<MasterEvent> CanOpenMaster::drainEvents() {
    std::lock_guard lock(impl_->mutex);
    std::vector<MasterEvent> out(impl_->events.begin(), impl_->events.end());
    impl_->events.clear();
    return out;
}

MasterStats CanOpenMaster::stats() const {
    const Impl& m = *impl_;
    MasterStats s;
    s.cycles = m.cycles.load();
    s.completed_cycles = m.completed.load();
    s.frames_tx = m.framesTx.load();
    s.frames_rx = m.framesRx.load();
    s.last_urgent_ns = m.lastUrgentNs.load();
    s.last_urgent_cycle = m.lastUrgentCycle.load();
    std::vector<double> j;
    {
        std::lock_guard lock(m.mutex);
        j = m.jitterUs;
    }
    if (!j.empty()) {
        std::sort(j.begin(), j.end());
        s.sync_jitter_us_p50 = j[j.size() / 2];
        s.sync_jitter_us_p99 = j[std::min(j.size() - 1, j.size() * 99 / 100)];
        s.sync_jitter_us_max = j.back();
    }
    return s;
}

void CanOpenMaster::resetJitter() {
    std::lock_guard lock(impl_->mutex);
    impl_->jitterUs.clear();
    impl_->jitterNext = 0;
}

std::string CanOpenMaster::loadText() const {
    return impl_->loadText;
}

void CanOpenMaster::Impl::event(int node, bool error, const std::string& text) {
    const std::string line =
        node ? messageC("node %d: %s", node, text.c_str()) : messageC("CAN bus: %s", text.c_str());
    if (error)
        qCWarning(lcCanOpen, "%s", line.c_str());
    else
        qCInfo(lcCanOpen, "%s", line.c_str());
    const MasterEvent e{QDateTime::currentMSecsSinceEpoch(), node, error, line};
    {
        std::lock_guard lock(mutex);
        if (events.size() >= 1000) events.pop_front();
        events.push_back(e);
    }
    if (sink) sink(e);
}

void CanOpenMaster::Impl::setFault(size_t i, std::uint32_t code, const std::string& text) {
    {
        std::lock_guard lock(mutex);
        faultText[i] = text;
    }
    // A reset asked before this fault does not clear it (master thread: rt is its own).
    rt[i].cleared_resets = shared[i].fault_reset_requests.load(std::memory_order_acquire);
    // The event first: whoever reacts to the fault (the engine) finds its reason logged.
    event(cfg.nodes[i].node, true, text);
    shared[i].master_fault.store(code, std::memory_order_release);
}

} // namespace cutcell::canopen
