#include "devices/canopen/drive_simulator.h"
#include "devices/canopen/thread_priority.h"

#include "devices/canopen/can_interface.h"
#include "devices/canopen/qt_can_frame.h"
#include "devices/canopen/virtualcan_host.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QThread>
#include <QTimer>

#include <chrono>

namespace cutcell::canopen {

DriveSimulator::DriveSimulator(DriveSimulatorConfig config) : config_(std::move(config)) {
    for (const DriveNodeConfig& c : config_.nodes)
        nodes_.emplace_back(c);
    for (const EncoderNodeConfig& c : config_.encoders)
        encoders_.emplace_back(c);
}

DriveSimulator::~DriveSimulator() {
    stop();
}

double DriveSimulator::now() const {
    const auto ns = std::chrono::steady_clock::now().time_since_epoch().count() - startNs_;
    return static_cast<double>(ns) * 1e-9;
}

bool DriveSimulator::start(int timeout_ms) {
    if (thread_) return true;
    startNs_ = std::chrono::steady_clock::now().time_since_epoch().count();
    thread_ = std::make_unique<QThread>();
    thread_->setObjectName(QStringLiteral("drivesim"));
    context_ = new QObject;
    context_->moveToThread(thread_.get());
    thread_->start();
    QMetaObject::invokeMethod(
        context_, [this] { openOnThread(); }, Qt::QueuedConnection);
    std::unique_lock lock(mutex_);
    const bool done = changed_.wait_for(lock, std::chrono::milliseconds(timeout_ms),
                                        [this] { return connected_ || failed_; });
    if (!done)
        error_ = QStringLiteral("CAN connection to %1 %2 did not come up within %3 ms")
                     .arg(config_.plugin, config_.interface)
                     .arg(timeout_ms);
    const bool ok = connected_;
    lock.unlock();
    if (!ok) stop();
    return ok;
}

void DriveSimulator::stop() {
    if (!thread_) return;
    QMetaObject::invokeMethod(
        context_, [this] { closeOnThread(); }, Qt::BlockingQueuedConnection);
    thread_->quit();
    thread_->wait();
    delete context_;
    context_ = nullptr;
    thread_.reset();
}

void DriveSimulator::injectFault(int node, std::uint16_t code) {
    if (!context_) return;
    QMetaObject::invokeMethod(
        context_,
        [this, node, code] {
            out_.clear();
            for (DriveNode& n : nodes_)
                if (n.node() == node) n.injectFault(code, out_);
            send(out_);
            publish();
        },
        Qt::QueuedConnection);
}

void DriveSimulator::stopHeartbeat(int node) {
    if (!context_) return;
    QMetaObject::invokeMethod(
        context_,
        [this, node] {
            for (DriveNode& n : nodes_)
                if (n.node() == node) n.stopHeartbeat();
            for (EncoderNode& n : encoders_)
                if (n.node() == node) n.stopHeartbeat();
        },
        Qt::QueuedConnection);
}

void DriveSimulator::stopPdo(int node) {
    if (!context_) return;
    QMetaObject::invokeMethod(
        context_,
        [this, node] {
            for (EncoderNode& n : encoders_)
                if (n.node() == node) n.stopPdo();
        },
        Qt::QueuedConnection);
}

QString DriveSimulator::errorText() const {
    std::lock_guard lock(mutex_);
    return error_;
}

std::vector<SimNodeSnapshot> DriveSimulator::snapshot() const {
    std::lock_guard lock(mutex_);
    return snapshot_;
}

std::uint64_t DriveSimulator::framesReceived() const {
    std::lock_guard lock(mutex_);
    return framesReceived_;
}

void DriveSimulator::openOnThread() {
    raiseCallingThreadToFifo(kSimulatorThreadPriority); // best effort (thread_priority.h)
    if (std::string why; !checkCanInterface(config_.plugin, config_.interface, &why)) {
        std::lock_guard lock(mutex_);
        error_ = QString::fromStdString(why);
        failed_ = true;
        changed_.notify_all();
        return;
    }
    // The first on a virtualcan bus hosts it: through CutCell's checking relay, not the plugin's.
    hostVirtualCanBus(config_.plugin, config_.interface);
    QString err;
    device_ = QCanBus::instance()->createDevice(config_.plugin, config_.interface, &err);
    auto fail = [this](const QString& text) {
        std::lock_guard lock(mutex_);
        error_ = text;
        failed_ = true;
        changed_.notify_all();
    };
    if (!device_) {
        fail(QStringLiteral("cannot create CAN device %1 %2: %3")
                 .arg(config_.plugin, config_.interface, err));
        return;
    }
    QObject::connect(device_, &QCanBusDevice::framesReceived, context_,
                     [this] { onFramesReceived(); });
    QObject::connect(device_, &QCanBusDevice::stateChanged, context_,
                     [this](QCanBusDevice::CanBusDeviceState s) {
                         if (s != QCanBusDevice::ConnectedState) return;
                         setLowDelay(device_, config_.plugin, config_.interface);
                         std::vector<CanFrame> boot;
                         for (DriveNode& n : nodes_)
                             n.boot(now(), boot);
                         for (EncoderNode& n : encoders_)
                             n.boot(now(), boot);
                         send(boot);
                         publish();
                         std::lock_guard lock(mutex_);
                         connected_ = true;
                         changed_.notify_all();
                     });
    QObject::connect(device_, &QCanBusDevice::errorOccurred, context_,
                     [this, fail](QCanBusDevice::CanBusError) {
                         if (!connected_) fail(device_->errorString());
                     });
    if (!device_->connectDevice()) {
        fail(QStringLiteral("cannot connect CAN device %1 %2: %3")
                 .arg(config_.plugin, config_.interface, device_->errorString()));
        return;
    }
    tick_ = new QTimer(context_);
    tick_->setTimerType(Qt::PreciseTimer);
    QObject::connect(tick_, &QTimer::timeout, context_, [this] { onTick(); });
    tick_->start(2);
}

void DriveSimulator::closeOnThread() {
    delete tick_;
    tick_ = nullptr;
    if (device_) {
        device_->disconnectDevice();
        delete device_;
        device_ = nullptr;
    }
}

void DriveSimulator::onFramesReceived() {
    std::uint64_t count = 0;
    // Not connected (the relay dropped the client): readFrame() fails and leaves the frame
    // queued, so the loop would never end.
    if (!device_ || device_->state() != QCanBusDevice::ConnectedState) return;
    while (device_->framesAvailable()) {
        const QCanBusFrame q = device_->readFrame();
        CanFrame f;
        if (!fromQt(q, f)) continue;
        ++count;
        out_.clear();
        const double t = now();
        // Encoders first: at a SYNC they sample the mechanism before the drives move it on.
        for (EncoderNode& n : encoders_)
            n.handle(f, t, out_);
        for (DriveNode& n : nodes_)
            n.handle(f, t, out_);
        // Nodes on coupled mechanics: their loop steps of the cycle a SYNC started, in turn.
        for (bool any = true; any;) {
            any = false;
            for (DriveNode& n : nodes_)
                if (n.hasDeferredStep()) {
                    n.runDeferredStep(out_);
                    any = true;
                }
        }
        send(out_);
    }
    publish();
    std::lock_guard lock(mutex_);
    framesReceived_ += count;
}

void DriveSimulator::onTick() {
    // A simulated drive's process can stall on a loaded host, which a drive's firmware does
    // not: frames the master sent meanwhile may still wait in the socket (the bus's server
    // relays them on the same thread). After a stall this tick only takes in what the device
    // holds; the nodes judge the master's silence at the next one, once they are delivered.
    onFramesReceived();
    const double t = now();
    constexpr double kStallS = 0.05; // 25 ticks
    const bool stalled = lastTick_s_ >= 0 && t - lastTick_s_ > kStallS && !tickDeferred_;
    tickDeferred_ = stalled;
    lastTick_s_ = t;
    if (stalled) return;
    out_.clear();
    for (DriveNode& n : nodes_)
        n.tick(t, out_);
    for (EncoderNode& n : encoders_)
        n.tick(t, out_);
    send(out_);
    publish();
}

void DriveSimulator::send(const std::vector<CanFrame>& frames) {
    if (!device_ || device_->state() != QCanBusDevice::ConnectedState) return;
    for (const CanFrame& f : frames)
        device_->writeFrame(toQt(f));
}

void DriveSimulator::publish() {
    std::lock_guard lock(mutex_);
    snapshot_.resize(nodes_.size() + encoders_.size());
    for (size_t i = 0; i < nodes_.size(); ++i) {
        const DriveNode& n = nodes_[i];
        snapshot_[i] = {n.node(),          n.nmtState(),       n.driveState(),
                        n.positionRad(),   n.errorCode(),      n.syncCount(),
                        n.appliedTorque(), n.disabledAtSync(), false};
    }
    for (size_t i = 0; i < encoders_.size(); ++i) {
        const EncoderNode& n = encoders_[i];
        snapshot_[nodes_.size() + i] = {n.node(),
                                        n.nmtState(),
                                        Cia402State::Unknown,
                                        static_cast<double>(n.lastCounts()),
                                        0,
                                        n.syncCount(),
                                        0,
                                        0,
                                        true};
    }
}

} // namespace cutcell::canopen
