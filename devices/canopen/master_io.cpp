// The CANopen master's bus work, all on the master thread: device, start-up of the nodes by
// SDO, the cycle (RPDO1s + SYNC), urgent stops (RPDO2), TPDO/heartbeat/EMCY consumers, bus
// state. See canopen_master.h for the protocol and the threading contract.
#include "core/common/c_format.h"
#include "devices/canopen/bus_load.h"
#include "devices/canopen/can_interface.h"
#include "devices/canopen/emcy.h"
#include "devices/canopen/master_impl.h"
#include "devices/canopen/nmt.h"
#include "devices/canopen/qt_can_frame.h"
#include "devices/canopen/sdo.h"
#include "devices/canopen/virtualcan_host.h"

#include <QCanBus>
#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QVariant>

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace cutcell::canopen {
namespace {

std::string hex(std::uint32_t v, int digits) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%0*X", digits, static_cast<unsigned>(v));
    return buf;
}

std::uint64_t drain(int fd) {
    std::uint64_t n = 0;
    if (::read(fd, &n, sizeof n) != static_cast<ssize_t>(sizeof n)) return 0;
    return n;
}

} // namespace

bool CanOpenMaster::Impl::send(const CanFrame& f) {
    // Nothing goes out while listening, after a refusal or after giving the bus up.
    if (!busTaken || !device || device->state() != QCanBusDevice::ConnectedState) return false;
    if (!device->writeFrame(toQt(f))) return false;
    framesTx.fetch_add(1, std::memory_order_relaxed);
    return true;
}

void CanOpenMaster::Impl::openDevice() {
    // This thread ends with stop(): the virtualcan bus, if this process hosts it, must not.
    hostVirtualCanBus(cfg.plugin, cfg.interface);
    QString err;
    device = QCanBus::instance()->createDevice(cfg.plugin, cfg.interface, &err);
    auto fail = [this](const std::string& why) {
        std::lock_guard lock(mutex);
        connectFailed = true;
        connectError = why;
        bus = BusState::Disconnected;
        busText = why;
        changed.notify_all();
    };
    if (!device) {
        fail(messageC("cannot create CAN device %s %s: %s", cfg.plugin.toStdString().c_str(),
                      cfg.interface.toStdString().c_str(), err.toStdString().c_str()));
        return;
    }
    if (cfg.plugin == QLatin1String("socketcan")) {
        device->setConfigurationParameter(QCanBusDevice::BitRateKey, QVariant(cfg.bitrate_bps));
        // Ask the kernel for error frames: bus-off, controller (error passive), restarted.
        device->setConfigurationParameter(
            QCanBusDevice::ErrorFilterKey,
            QVariant::fromValue(QCanBusFrame::FrameErrors(QCanBusFrame::AnyError)));
    }
    QObject::connect(device, &QCanBusDevice::framesReceived, context, [this] { onFrames(); });
    QObject::connect(device, &QCanBusDevice::stateChanged, context,
                     [this](QCanBusDevice::CanBusDeviceState s) { onStateChanged(s); });
    QObject::connect(
        device, &QCanBusDevice::errorOccurred, context, [this, fail](QCanBusDevice::CanBusError e) {
            const std::string why = device->errorString().toStdString();
            bool wasConnected;
            {
                std::lock_guard lock(mutex);
                wasConnected = connected;
            }
            if (!wasConnected)
                fail(messageC("CAN device %s %s: %s", cfg.plugin.toStdString().c_str(),
                              cfg.interface.toStdString().c_str(), why.c_str()));
            else
                event(0, e != QCanBusDevice::NoError, messageC("device error: %s", why.c_str()));
        });
    if (!wakeNotifier) {
        wakeNotifier = new QSocketNotifier(wakeFd, QSocketNotifier::Read, context);
        QObject::connect(wakeNotifier, &QSocketNotifier::activated, context, [this] { onWake(); });
        syncNotifier = new QSocketNotifier(syncFd, QSocketNotifier::Read, context);
        QObject::connect(syncNotifier, &QSocketNotifier::activated, context,
                         [this] { onSyncDue(); });
        housekeeping = new QTimer(context);
        QObject::connect(housekeeping, &QTimer::timeout, context, [this] { onHousekeeping(); });
        housekeeping->start(5);
    }
    if (!device->connectDevice()) {
        fail("cannot connect CAN device " + cfg.plugin.toStdString() + " " +
             cfg.interface.toStdString() + ": " + device->errorString().toStdString());
    }
}

void CanOpenMaster::Impl::writeDisableAll() {
    if (!busTaken) return; // never write on a bus another master owns
    for (size_t i = 0; i < shared.size(); ++i)
        if (!cfg.nodes[i].encoder) send(encodeRpdo2(cfg.nodes[i].node, cw::kDisableVoltage));
    send(encodeNmt(NmtCommand::EnterPreOperational, 0));
    flushDevice(device);
}

void CanOpenMaster::Impl::closeDevice() {
    stopping = true;
    if (!device) return;
    // Leave the drives without torque and the nodes pre-operational.
    writeDisableAll();
    busTaken = false;
    listening = false;
    // Let the transport write them out before the device goes (virtualcan buffers in a socket).
    const QDeadlineTimer flush(50);
    while (!flush.hasExpired())
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    if (device->state() != QCanBusDevice::UnconnectedState) device->disconnectDevice();
    delete device;
    device = nullptr;
    for (NodeShared& s : shared)
        s.configured = false;
    std::lock_guard lock(mutex);
    connected = taken = false;
}

void CanOpenMaster::Impl::onStateChanged(QCanBusDevice::CanBusDeviceState s) {
    if (s == QCanBusDevice::ConnectedState) {
        setLowDelay(device, cfg.plugin, cfg.interface);
        {
            std::lock_guard lock(mutex);
            connected = true;
            bus = BusState::Good;
            busText =
                "connected to " + cfg.plugin.toStdString() + " " + cfg.interface.toStdString();
        }
        // Listen first: the bus may already have a master (a second `run` on a cutting cell).
        const std::int64_t now = steadyNs();
        listening = true;
        heardSync = heardNmt = heardMasterHeartbeat = 0;
        heardNmtText.clear();
        listenUntilNs = now + static_cast<std::int64_t>(cfg.listen_before_start_ms) * 1'000'000;
        if (cfg.listen_before_start_ms <= 0) endListening(now);
    } else if (s == QCanBusDevice::UnconnectedState && !stopping) {
        busTaken = listening = false;
        onBusDown(BusState::Disconnected, master_fault::kBusLost,
                  messageC("connection to the bus lost"));
    }
}

void CanOpenMaster::Impl::onBusDown(BusState s, std::uint32_t code, const std::string& why) {
    {
        std::lock_guard lock(mutex);
        bus = s;
        busText = why;
    }
    event(0, true,
          messageC("%s: every drive is in Fault; recover the bus, then reset the faults",
                   why.c_str()));
    for (size_t i = 0; i < shared.size(); ++i) {
        shared[i].configured = false;
        rt[i].phase = StartupPhase::Failed;
        setFault(i, code, messageC("CAN bus: %s", why.c_str()));
    }
}

// ---- listening before taking the bus, the master's heartbeat ------------------------------

// Frames only a master sends. virtualcan and socketcan do not echo our own frames, so any of
// these comes from someone else.
void CanOpenMaster::Impl::listenFor(const CanFrame& f) {
    NmtCommand c;
    int target = 0;
    int hbNode = 0;
    NmtState hbState;
    if (f.id == cob::kSync) {
        ++heardSync;
    } else if (decodeNmt(f, c, target)) {
        if (heardNmt++ == 0)
            heardNmtText = target ? messageC("NMT %s to node %d", toString(c), target)
                                  : messageC("NMT %s to all nodes", toString(c));
    } else if (cfg.master_node_id > 0 && decodeHeartbeat(f, hbNode, hbState) &&
               hbNode == cfg.master_node_id) {
        ++heardMasterHeartbeat;
    } else {
        return;
    }
    if (busTaken) {
        const std::string heard =
            f.id == cob::kSync ? messageC("a SYNC (0x080)")
            : f.id == cob::kNmt
                ? messageC("%s (0x000)",
                           target ? messageC("NMT %s to node %d", toString(c), target).c_str()
                                  : messageC("NMT %s to all nodes", toString(c)).c_str())
                : messageC("a heartbeat of the master's node %d (0x%03X)", cfg.master_node_id,
                           0x700u + cfg.master_node_id);
        onSecondMaster(heard);
    }
}

// A frame only a master sends, heard after this master took the bus: a second master (a CAN
// frame names no sender, and neither virtualcan nor socketcan gives a device its own frames
// back). Both masters hear each other within a cycle, so both stop: their drives disabled and
// pre-operational, every node in Fault, and this master sends nothing more until the bus is
// recovered (which listens again and refuses while the other is there).
void CanOpenMaster::Impl::onSecondMaster(const std::string& heard) {
    if (!busTaken) return;
    writeDisableAll();
    busTaken = false;
    onBusDown(BusState::Disconnected, master_fault::kOtherMaster,
              messageC("another CANopen master is on the bus (heard %s, not sent by this "
                       "master): every drive disabled and pre-operational, this master gave "
                       "up the bus",
                       heard.c_str()));
}

void CanOpenMaster::Impl::endListening(std::int64_t now) {
    listening = false;
    std::string heard;
    auto add = [&heard](const std::string& what) { heard += (heard.empty() ? "" : ", ") + what; };
    if (heardSync) add(messageC("%d SYNC (0x080)", heardSync));
    if (heardNmt)
        add(messageC(heardNmt > 1 ? "%d NMT commands (0x000, %s)" : "%d NMT command (0x000, %s)",
                     heardNmt, heardNmtText.c_str()));
    if (heardMasterHeartbeat)
        add(messageC(heardMasterHeartbeat > 1 ? "%d master heartbeats of node %d (0x%03X)"
                                              : "%d master heartbeat of node %d (0x%03X)",
                     heardMasterHeartbeat, cfg.master_node_id, 0x700u + cfg.master_node_id));
    if (!heard.empty()) {
        const std::string why = messageC(
            "another CANopen master is active on %s %s: heard %s within %d ms; not taking the bus",
            cfg.plugin.toStdString().c_str(), cfg.interface.toStdString().c_str(), heard.c_str(),
            cfg.listen_before_start_ms);
        {
            std::lock_guard lock(mutex);
            connectFailed = true;
            connectError = why;
            bus = BusState::Disconnected;
            busText = why;
            changed.notify_all();
        }
        for (size_t i = 0; i < rt.size(); ++i) {
            rt[i].phase = StartupPhase::Failed;
            setFault(i, master_fault::kOtherMaster, why);
        }
        stopping = true;
        device->disconnectDevice();
        return;
    }
    busTaken = true;
    nextMasterHeartbeatNs = now;
    {
        std::lock_guard lock(mutex);
        taken = true;
        changed.notify_all();
    }
    event(0, false,
          messageC("connected, no other master heard in %d ms; %s", cfg.listen_before_start_ms,
                   loadText.c_str()));
    produceHeartbeat(now);
    for (size_t i = 0; i < rt.size(); ++i)
        startNode(i, now);
}

void CanOpenMaster::Impl::produceHeartbeat(std::int64_t now) {
    if (!busTaken || cfg.master_node_id <= 0 || now < nextMasterHeartbeatNs) return;
    send(encodeHeartbeat(cfg.master_node_id, NmtState::Operational));
    const std::int64_t period = static_cast<std::int64_t>(heartbeatProducerMs) * 1'000'000;
    nextMasterHeartbeatNs += period;
    if (nextMasterHeartbeatNs < now) nextMasterHeartbeatNs = now + period; // fell behind
}

// ---- start-up of one node ----------------------------------------------------------------

void CanOpenMaster::Impl::startNode(size_t i, std::int64_t now) {
    NodeRuntime& r = rt[i];
    const int node = cfg.nodes[i].node;
    shared[i].configured = false;
    // A (re)started node waits for an explicit activate(): never enable behind the engine's back.
    shared[i].goal.store(static_cast<std::uint8_t>(DriveGoal::Disabled), std::memory_order_release);
    r.phase = StartupPhase::WaitBoot;
    r.deadline_ns = now + static_cast<std::int64_t>(cfg.boot_timeout_ms) * 1'000'000;
    r.ops.clear();
    r.op = 0;
    r.retries = 0;
    r.was_enabled = false;
    send(encodeNmt(NmtCommand::ResetCommunication, node));
}

void CanOpenMaster::Impl::nextSdo(size_t i, std::int64_t now) {
    NodeRuntime& r = rt[i];
    const int node = cfg.nodes[i].node;
    if (r.op >= r.ops.size()) {
        r.phase = StartupPhase::WaitOperational;
        r.deadline_ns = now + static_cast<std::int64_t>(cfg.boot_timeout_ms) * 1'000'000;
        send(encodeNmt(NmtCommand::Start, node));
        return;
    }
    const SdoOp& op = r.ops[r.op];
    send(op.upload ? sdoUploadRequest(node, op.write.address)
                   : sdoDownloadRequest(node, op.write.address, op.write.value, op.write.size));
    r.deadline_ns = now + static_cast<std::int64_t>(cfg.sdo_timeout_ms) * 1'000'000;
}

void CanOpenMaster::Impl::onSdoReply(size_t i, const CanFrame& f, std::int64_t now) {
    NodeRuntime& r = rt[i];
    if (r.phase != StartupPhase::Sdo || r.op >= r.ops.size()) return;
    const SdoOp& op = r.ops[r.op];
    const SdoMessage m = decodeSdo(f);
    if (!(m.address == op.write.address)) return; // a late answer to an earlier try
    const std::string index = hex(op.write.address.index, 4);
    const std::string sub = hex(op.write.address.sub, 2).substr(2);
    const std::string what = op.upload
                                 ? messageC("SDO read %s:%s", index.c_str(), sub.c_str())
                                 : messageC("SDO write %s:%s = %s", index.c_str(), sub.c_str(),
                                            hex(op.write.value, 2 * op.write.size).c_str());
    if (m.kind == SdoKind::Abort) {
        r.phase = StartupPhase::Failed;
        // A node without the SYNC counter's object: the job can do without the counter.
        const bool counter = op.write.address.index == od::kSyncCounterOverflow && !op.upload;
        setFault(i, m.value,
                 counter ? messageC("%s refused: %s (a node without a SYNC counter: set "
                                    "devices.sync_counter_overflow = 0)",
                                    what.c_str(), sdoAbortText(m.value).c_str())
                         : messageC("%s refused: %s", what.c_str(), sdoAbortText(m.value).c_str()));
        return;
    }
    if ((op.upload && m.kind != SdoKind::UploadResponse) ||
        (!op.upload && m.kind != SdoKind::DownloadResponse)) {
        r.phase = StartupPhase::Failed;
        setFault(i, abort_code::kUnknownCommand,
                 messageC("%s: unexpected SDO answer (segmented transfer?)", what.c_str()));
        return;
    }
    const bool encoder = cfg.nodes[i].encoder;
    if (op.upload && op.write.address.index == od::kDeviceType &&
        (m.value & 0xFFFF) != (encoder ? 406u : 402u)) {
        r.phase = StartupPhase::Failed;
        setFault(i, master_fault::kWrongDevice,
                 messageC(encoder ? "device type %s is not a CiA 406 encoder (profile %u)"
                                  : "device type %s is not a CiA 402 drive (profile %u)",
                          hex(m.value, 8).c_str(), static_cast<unsigned>(m.value & 0xFFFF)));
        return;
    }
    if (op.upload && op.write.address.index == od::kMotorRatedTorque) {
        if (m.value == 0) {
            r.phase = StartupPhase::Failed;
            setFault(i, abort_code::kValueTooLow,
                     messageC("motor rated torque 0x6076 = 0: no scale for the target torque "
                              "(CST)"));
            return;
        }
        shared[i].rated_torque.store(m.value * 1e-3, std::memory_order_release);
    }
    ++r.op;
    r.retries = 0;
    nextSdo(i, now);
}

// ---- frames in ---------------------------------------------------------------------------

void CanOpenMaster::Impl::onFrames() {
    const std::int64_t now = steadyNs();
    // Not connected (closing, refused the bus): readFrame() fails and leaves the frame queued.
    while (device && device->state() == QCanBusDevice::ConnectedState &&
           device->framesAvailable()) {
        const QCanBusFrame q = device->readFrame();
        framesRx.fetch_add(1, std::memory_order_relaxed);
        if (q.frameType() == QCanBusFrame::ErrorFrame) {
            onErrorFrame(q.frameId(), q.payload());
            continue;
        }
        CanFrame f;
        if (fromQt(q, f)) onFrame(f, now);
    }
}

void CanOpenMaster::Impl::onErrorFrame(std::uint32_t errorClass, const QByteArray& payload) {
    const ErrorFrameInfo info =
        decodeErrorFrame(errorClass, reinterpret_cast<const std::uint8_t*>(payload.constData()),
                         static_cast<int>(payload.size()));
    if (info.state == BusState::BusOff) {
        onBusDown(BusState::BusOff, master_fault::kBusOff,
                  messageC("bus off (%s)", info.text.c_str()));
        return;
    }
    {
        std::lock_guard lock(mutex);
        if (info.state != BusState::Unknown) bus = info.state;
        busText = info.text;
    }
    event(0, info.state == BusState::ErrorPassive || info.state == BusState::Warning, info.text);
}

void CanOpenMaster::Impl::onFrame(const CanFrame& f, std::int64_t now) {
    if (f.id == cob::kSync || f.id == cob::kNmt ||
        (cfg.master_node_id > 0 &&
         f.id == cob::kHeartbeat + static_cast<std::uint32_t>(cfg.master_node_id))) {
        listenFor(f);
        return;
    }
    if (listening) return;
    const int node = cob::nodeOf(f.id);
    size_t i = 0;
    while (i < cfg.nodes.size() && cfg.nodes[i].node != node)
        ++i;
    if (i == cfg.nodes.size()) return; // not one of ours (or a frame of the master's kind)
    NodeShared& s = shared[i];
    NodeRuntime& r = rt[i];
    const std::uint32_t function = cob::functionOf(f.id);
    if (!cfg.nodes[i].encoder && (function == cob::kRpdo1 || function == cob::kRpdo2)) {
        onSecondMaster(messageC("a %s to node %d (0x%03X)",
                                function == cob::kRpdo1 ? "RPDO1" : "RPDO2", node, f.id));
        return;
    }
    std::int32_t encoderCounts = 0;
    if (cfg.nodes[i].encoder && decodeEncoderTpdo(f, encoderCounts)) {
        r.awaiting_since_ns = 0;
        s.velocity_counts_s.store((encoderCounts - r.previous_actual) / cfg.period_s,
                                  std::memory_order_relaxed);
        r.previous_actual = encoderCounts;
        s.tpdo_seq.store(r.answered(), std::memory_order_relaxed); // published by the next store
        s.actual_counts.store(encoderCounts, std::memory_order_release);
        s.tpdo_ns.store(now, std::memory_order_release);
        s.tpdo_count.fetch_add(1, std::memory_order_relaxed);
        noteCycleAnswer(i);
        return;
    }
    Tpdo1 t;
    if (!cfg.nodes[i].encoder && decodeTpdo1(f, t)) {
        const Cia402State state = decodeStatusword(t.statusword);
        const bool enabled = state == Cia402State::OperationEnabled;
        if (enabled && !r.was_enabled) s.enable_epoch.fetch_add(1, std::memory_order_acq_rel);
        r.was_enabled = enabled;
        s.velocity_counts_s.store((t.actual_counts - r.previous_actual) / cfg.period_s,
                                  std::memory_order_relaxed);
        r.previous_actual = t.actual_counts;
        s.tpdo_seq.store(r.answered(), std::memory_order_relaxed); // published by the next store
        s.actual_counts.store(t.actual_counts, std::memory_order_release);
        s.torque_permille.store(t.torque_permille, std::memory_order_relaxed);
        s.tpdo_ns.store(now, std::memory_order_release);
        s.statusword.store(t.statusword, std::memory_order_release);
        s.tpdo_count.fetch_add(1, std::memory_order_relaxed);
        // SYNCs still unanswered were sent before now: counting from here is on the safe side.
        r.awaiting_since_ns = r.unansweredCount > 0 ? now : 0;
        noteCycleAnswer(i);
        return;
    }
    int hbNode = 0;
    NmtState nmt;
    if (decodeHeartbeat(f, hbNode, nmt)) {
        s.heartbeat_ns.store(now, std::memory_order_release);
        s.nmt.store(static_cast<std::uint8_t>(nmt), std::memory_order_release);
        if (nmt == NmtState::BootUp) {
            // A node that (re)booted has no power stage state yet: forget the statusword it sent
            // before (e.g. Operation Enabled before a bus loss) until its first new TPDO.
            s.statusword.store(0, std::memory_order_release);
            if (r.phase == StartupPhase::WaitBoot) {
                r.phase = StartupPhase::Sdo;
                r.ops.clear();
                r.ops.push_back({{{od::kDeviceType, 0}, 0, 0}, true});
                DriveConfig dc;
                dc.cycle_period_us = static_cast<std::uint32_t>(cfg.period_s * 1e6 + 0.5);
                dc.heartbeat_ms = heartbeatProducerMs;
                dc.master_node = cfg.master_node_id;
                dc.master_heartbeat_timeout_ms = static_cast<std::uint16_t>(
                    std::clamp(cfg.heartbeat_timeout_s * 1e3, 1.0, 65535.0));
                dc.abort_connection_option = cfg.abort_connection_option;
                dc.sync_counter_overflow = syncOverflow();
                const MasterNodeConfig& nc = cfg.nodes[i];
                const bool torque = !nc.encoder && nc.mode == AxisCommandMode::Torque;
                const std::vector<SdoWrite> writes =
                    nc.encoder ? encoderStartupWrites(node, heartbeatProducerMs, syncOverflow())
                    : torque   ? cstStartupWrites(node, dc)
                               : cspStartupWrites(node, dc);
                for (const SdoWrite& w : writes)
                    r.ops.push_back({w, false});
                if (torque) r.ops.push_back({{{od::kMotorRatedTorque, 0}, 0, 0}, true});
                r.op = 0;
                nextSdo(i, now);
            } else if (r.phase == StartupPhase::Running) {
                s.configured = false;
                r.phase = StartupPhase::Failed;
                // A real reboot leaves the drive without torque; a node that only says so (or
                // was reset by someone else) might still listen: disable it too.
                if (!cfg.nodes[i].encoder) {
                    send(encodeRpdo2(node, cw::kDisableVoltage));
                    flushDevice(device);
                }
                setFault(i, master_fault::kRebooted,
                         messageC("node rebooted while running (unexpected boot-up)"));
            }
        } else if (nmt == NmtState::Operational && r.phase == StartupPhase::WaitOperational) {
            r.phase = StartupPhase::Running;
            r.tpdo_cycle = cycles.load(std::memory_order_relaxed);
            r.unansweredCount = 0;   // SYNCs from now on
            r.awaiting_since_ns = 0; // not the SYNCs before a bus loss or a reboot
            s.master_fault.store(0, std::memory_order_release);
            {
                std::lock_guard lock(mutex);
                faultText[i].clear();
            }
            s.configured = true;
            const bool torque = cfg.nodes[i].mode == AxisCommandMode::Torque;
            event(node, false,
                  messageC(cfg.nodes[i].encoder
                               ? "configured (CiA 406 encoder, TPDO1 position value, heartbeat "
                                 "%d ms) and operational"
                           : torque ? "configured (CST, RPDO1/RPDO2/TPDO1, heartbeat %d ms) and "
                                      "operational"
                                    : "configured (CSP, RPDO1/RPDO2/TPDO1, heartbeat %d ms) and "
                                      "operational",
                           heartbeatProducerMs));
        }
        return;
    }
    Emcy e;
    if (decodeEmcy(f, e)) {
        s.last_emcy.store(e.error_code, std::memory_order_release);
        const std::string text =
            messageC("EMCY %s (error register %s)", canopen::emcyText(e.error_code).c_str(),
                     hex(e.error_register, 2).c_str());
        {
            std::lock_guard lock(mutex);
            emcyText[i] = e.error_code ? text : std::string();
        }
        event(node, e.error_code != 0, text);
        // An error from a node in use faults the cell: the engine sees the drive in Fault and
        // stops everything; this drive loses its torque now. EMCY 0x0000 (error reset) is news.
        if (e.error_code != 0 && r.phase == StartupPhase::Running && s.master_fault.load() == 0) {
            r.emcy_fault = true;
            if (!cfg.nodes[i].encoder) {
                send(encodeRpdo2(node, cw::kDisableVoltage));
                flushDevice(device);
            }
            setFault(i, e.error_code, text);
        }
        return;
    }
    if (cob::functionOf(f.id) == cob::kSdoTx) onSdoReply(i, f, now);
}

// The cycle is complete when every running node has answered this SYNC.
void CanOpenMaster::Impl::noteCycleAnswer(size_t i) {
    const std::uint64_t c = cycles.load(std::memory_order_relaxed);
    rt[i].tpdo_cycle = c;
    bool all = true;
    for (size_t k = 0; k < rt.size(); ++k)
        if (rt[k].phase == StartupPhase::Running && rt[k].tpdo_cycle != c) all = false;
    if (all) completed.store(c, std::memory_order_release);
}

// ---- commands, cycle, housekeeping -------------------------------------------------------

std::uint16_t CanOpenMaster::Impl::controlwordFor(size_t i) {
    NodeShared& s = shared[i];
    NodeRuntime& r = rt[i];
    const std::uint32_t resets = s.fault_reset_requests.load(std::memory_order_acquire);
    if (resets != r.seen_resets) {
        r.seen_resets = resets;
        r.reset_phase = 1;
    }
    if (r.reset_phase == 1) {
        r.reset_phase = 2;
        return cw::kDisableVoltage; // bit 7 low ...
    }
    if (r.reset_phase == 2) {
        r.reset_phase = 0;
        return cw::kFaultResetBit; // ... then high: the rising edge
    }
    const Cia402State state = decodeStatusword(s.statusword.load(std::memory_order_acquire));
    if (s.master_fault.load(std::memory_order_acquire) != 0) return cw::kDisableVoltage;
    return controlwordToward(state, static_cast<DriveGoal>(s.goal.load(std::memory_order_acquire)));
}

void CanOpenMaster::Impl::onWake() {
    drain(wakeFd);
    const std::int64_t now = steadyNs();
    bool sent = false;
    for (size_t i = 0; i < shared.size(); ++i) {
        NodeShared& s = shared[i];
        // A fault reset of a master-side fault: clear it when its cause is gone, else start
        // the node again (reset communication, SDO configuration). A request that finds no
        // way yet (the bus down, the node starting) waits for the next wake-up.
        const std::uint32_t resets = s.fault_reset_requests.load(std::memory_order_acquire);
        const std::uint32_t fault = s.master_fault.load(std::memory_order_acquire);
        if (resets != rt[i].cleared_resets && fault == 0) {
            rt[i].cleared_resets = resets; // nothing of the master's to clear
        } else if (resets != rt[i].cleared_resets) {
            const bool heartbeatFresh = now - s.heartbeat_ns.load() < heartbeatTimeoutNs;
            // An EMCY's fault: the drive's own reset (the controlword's rising edge) follows.
            const bool emcyOnly = rt[i].emcy_fault && heartbeatFresh;
            if (((fault == master_fault::kHeartbeatLost && heartbeatFresh) || emcyOnly) &&
                rt[i].phase == StartupPhase::Running) {
                rt[i].cleared_resets = resets;
                rt[i].emcy_fault = false;
                s.master_fault.store(0, std::memory_order_release);
                std::lock_guard lock(mutex);
                faultText[i].clear();
            } else if (device && device->state() == QCanBusDevice::ConnectedState &&
                       (rt[i].phase == StartupPhase::Failed ||
                        rt[i].phase == StartupPhase::Running)) {
                rt[i].cleared_resets = resets;
                event(cfg.nodes[i].node, false,
                      messageC("fault reset: configuring the node again"));
                startNode(i, now);
            }
        }
        if (!s.urgent.exchange(false, std::memory_order_acq_rel) || cfg.nodes[i].encoder) continue;
        const Cia402State state = decodeStatusword(s.statusword.load(std::memory_order_acquire));
        const auto goal = static_cast<DriveGoal>(s.goal.load(std::memory_order_acquire));
        sent = send(encodeRpdo2(cfg.nodes[i].node, controlwordToward(state, goal))) || sent;
    }
    // Every stop frame of this wake-up in one write (with TCP_NODELAY: at once on the wire).
    if (sent) {
        flushDevice(device);
        lastUrgentCycle.store(cycles.load(std::memory_order_acquire), std::memory_order_release);
        lastUrgentNs.store(steadyNs(), std::memory_order_release);
    }
}

void CanOpenMaster::Impl::onSyncDue() {
    const std::uint64_t due = drain(syncFd);
    if (due == 0) return;
    // Paced by the engine, one SYNC per engine cycle even when this thread was held up and
    // several are due: the drives' cycle is the engine's (a simulated drive moves one period per
    // SYNC; one SYNC for three engine cycles left it two periods behind the engine's time, a
    // following error the drive never had). Paced by the clock (Internal): one, late.
    const std::uint64_t syncs = cfg.sync == SyncSource::LastDriveWrite
                                    ? std::min<std::uint64_t>(due, NodeRuntime::kMaxUnanswered)
                                    : 1;
    const std::int64_t now = steadyNs();
    for (std::uint64_t k = 0; k < syncs; ++k)
        runCycle(now);
}

// The target for this SYNC. Paced by the engine (one SYNC per write): the engine cycle after
// the one sent last while the ring still has it (several SYNCs due at once: each cycle's own).
// Paced by the clock: the newest. Notes the SYNC's cycle for pairing the answers.
std::uint64_t CanOpenMaster::Impl::cycleTarget(size_t i) {
    NodeShared& s = shared[i];
    NodeRuntime& r = rt[i];
    const std::uint64_t newest = s.write_seq.load(std::memory_order_acquire);
    std::uint64_t seq = r.sync_seq + 1;
    if (cfg.sync != SyncSource::LastDriveWrite || r.sync_seq == 0 || seq > newest ||
        newest - seq >= NodeShared::kTargetRing - 1)
        seq = newest;
    const std::uint64_t tagged =
        seq == 0 ? s.tagged_target.load(std::memory_order_acquire)
                 : s.targets[seq % NodeShared::kTargetRing].load(std::memory_order_relaxed);
    r.syncSent(seq);
    return tagged;
}

void CanOpenMaster::Impl::runCycle(std::int64_t now) {
    if (!device || device->state() != QCanBusDevice::ConnectedState) return;
    if (!busTaken) { // gave the bus up: nothing to send, nobody to wait for
        completed.store(cycles.fetch_add(1, std::memory_order_acq_rel) + 1,
                        std::memory_order_release);
        return;
    }
    for (size_t i = 0; i < shared.size(); ++i) {
        if (rt[i].phase != StartupPhase::Running) continue;
        if (cfg.nodes[i].encoder) {
            // Supervised from the first SYNC after it runs: this SYNC wants its position.
            if (rt[i].awaiting_since_ns == 0) rt[i].awaiting_since_ns = now;
            continue;
        }
        NodeShared& s = shared[i];
        if (rt[i].awaiting_since_ns == 0) rt[i].awaiting_since_ns = now;
        const std::uint16_t c = controlwordFor(i);
        const std::uint64_t tagged = cycleTarget(i);
        const bool enabled = decodeStatusword(s.statusword.load()) == Cia402State::OperationEnabled;
        const bool current = enabled && NodeShared::epochOf(tagged) ==
                                            s.enable_epoch.load(std::memory_order_acquire);
        if (cfg.nodes[i].mode == AxisCommandMode::Torque) {
            // No torque unless the engine wrote one after seeing this enable.
            const std::int32_t permille = current ? NodeShared::countsOf(tagged) : 0;
            send(encodeRpdo1Torque(cfg.nodes[i].node, c,
                                   static_cast<std::int16_t>(std::clamp(permille, -32768, 32767))));
            continue;
        }
        // Hold the actual position unless the engine wrote a target after seeing this enable.
        const std::int32_t target = current ? NodeShared::countsOf(tagged)
                                            : s.actual_counts.load(std::memory_order_acquire);
        send(encodeRpdo1(cfg.nodes[i].node, {c, target}));
    }
    // The encoders answer this SYNC too: the engine cycle it belongs to, for their TPDOs.
    if (clockNode < rt.size())
        for (size_t i = 0; i < shared.size(); ++i)
            if (cfg.nodes[i].encoder && rt[i].phase == StartupPhase::Running)
                rt[i].syncSent(rt[clockNode].sync_seq);
    if (syncOverflow() > 0) syncCounter = nextSyncCounter(syncCounter, syncOverflow());
    send(encodeSync(syncCounter));
    cycles.fetch_add(1, std::memory_order_release);
    if (lastSyncNs != 0) {
        const double jitter =
            std::abs(static_cast<double>(now - lastSyncNs) * 1e-3 - cfg.period_s * 1e6);
        std::lock_guard lock(mutex);
        if (jitterUs.size() < 4096)
            jitterUs.push_back(jitter);
        else
            jitterUs[jitterNext] = jitter;
        jitterNext = (jitterNext + 1) % 4096;
    }
    lastSyncNs = now;
}

void CanOpenMaster::Impl::onHousekeeping() {
    onFrames(); // what the device already holds counts before any deadline
    const std::int64_t now = steadyNs();
    if (listening && now >= listenUntilNs) endListening(now);
    produceHeartbeat(now);
    // After a stall of this thread (a loaded host), frames that came during it may still wait
    // in the socket: no node's silence is judged until the event loop has delivered them.
    constexpr std::int64_t kStallNs = 50'000'000; // 10 housekeeping periods
    // Only one round is let go: a thread starved for good still judges every other round.
    const bool stalled =
        lastHousekeepingNs > 0 && now - lastHousekeepingNs > kStallNs && !housekeepingDeferred;
    housekeepingDeferred = stalled;
    lastHousekeepingNs = now;
    for (size_t i = 0; i < rt.size() && !stalled; ++i) {
        NodeRuntime& r = rt[i];
        NodeShared& s = shared[i];
        const int node = cfg.nodes[i].node;
        switch (r.phase) {
        case StartupPhase::WaitBoot:
            if (now > r.deadline_ns) {
                r.phase = StartupPhase::Failed;
                setFault(
                    i, master_fault::kNoBootUp,
                    messageC("no boot-up within %d ms after NMT reset communication (is a node "
                             "with this id on the bus?)",
                             cfg.boot_timeout_ms));
            }
            break;
        case StartupPhase::Sdo:
            if (now > r.deadline_ns) {
                if (r.retries++ < cfg.sdo_retries) {
                    nextSdo(i, now);
                } else {
                    const SdoAddress a = r.ops[r.op].write.address;
                    r.phase = StartupPhase::Failed;
                    send(sdoAbort(node, a, abort_code::kTimeout, false));
                    setFault(i, abort_code::kTimeout,
                             messageC("SDO %s:%s unanswered after %d tries of %d ms: %s",
                                      hex(a.index, 4).c_str(), hex(a.sub, 2).substr(2).c_str(),
                                      cfg.sdo_retries + 1, cfg.sdo_timeout_ms,
                                      sdoAbortText(abort_code::kTimeout).c_str()));
                }
            }
            break;
        case StartupPhase::WaitOperational:
            if (now > r.deadline_ns) {
                r.phase = StartupPhase::Failed;
                setFault(i, master_fault::kNoBootUp,
                         messageC("no Operational heartbeat after NMT start"));
            }
            break;
        case StartupPhase::Running: {
            const std::int64_t age = now - s.heartbeat_ns.load(std::memory_order_acquire);
            if (age > heartbeatTimeoutNs && s.master_fault.load() != master_fault::kHeartbeatLost) {
                setFault(i, master_fault::kHeartbeatLost,
                         messageC("heartbeat lost (none for %lld ms > %lld ms)",
                                  static_cast<long long>(age / 1'000'000),
                                  static_cast<long long>(heartbeatTimeoutNs / 1'000'000)));
                // The node may still listen: take its torque away at once.
                if (!cfg.nodes[i].encoder) send(encodeRpdo2(node, cw::kDisableVoltage));
            }
            // A node that stopped answering SYNCs (its process died, its cable came off) is
            // named with its heartbeat's age: lost altogether, or only its process data.
            const std::int64_t waited = r.awaiting_since_ns ? now - r.awaiting_since_ns : 0;
            if (waited > pdoTimeoutNs && s.master_fault.load() == 0) {
                const long long heartbeatAgeMs = static_cast<long long>(age / 1'000'000);
                setFault(i, master_fault::kNoProcessData,
                         cfg.nodes[i].encoder
                             ? messageC("no position value (TPDO) for %lld ms after a SYNC (> "
                                        "%lld ms): the encoder's reading is lost; last heartbeat "
                                        "%lld ms ago",
                                        static_cast<long long>(waited / 1'000'000),
                                        static_cast<long long>(pdoTimeoutNs / 1'000'000),
                                        heartbeatAgeMs)
                             : messageC("no process data (TPDO) for %lld ms after a SYNC (> %lld "
                                        "ms): the drive's feedback is lost; last heartbeat %lld "
                                        "ms ago",
                                        static_cast<long long>(waited / 1'000'000),
                                        static_cast<long long>(pdoTimeoutNs / 1'000'000),
                                        heartbeatAgeMs));
                if (!cfg.nodes[i].encoder) send(encodeRpdo2(node, cw::kDisableVoltage));
            }
            break;
        }
        default:
            break;
        }
    }
    if (device && device->hasBusStatus()) {
        const auto st = device->busStatus();
        const BusState b = st == QCanBusDevice::CanBusStatus::Good      ? BusState::Good
                           : st == QCanBusDevice::CanBusStatus::Warning ? BusState::Warning
                           : st == QCanBusDevice::CanBusStatus::Error   ? BusState::ErrorPassive
                           : st == QCanBusDevice::CanBusStatus::BusOff  ? BusState::BusOff
                                                                        : BusState::Unknown;
        BusState before;
        {
            std::lock_guard lock(mutex);
            before = bus;
        }
        if (b == BusState::BusOff && before != BusState::BusOff)
            onBusDown(b, master_fault::kBusOff, messageC("bus off"));
        else if (b != BusState::Unknown && b != before && before != BusState::BusOff) {
            {
                std::lock_guard lock(mutex);
                bus = b;
                busText = toString(b);
            }
            event(0, b != BusState::Good, messageC("bus state: %s", toString(b)));
        }
    }
}

} // namespace cutcell::canopen
