#pragma once
// Private to the CANopen master (canopen_master.cpp, master_io.cpp): its state on the master
// thread. Fields marked [master] are touched only on the master thread.
#include "devices/canopen/can_frame.h"
#include "devices/canopen/canopen_master.h"
#include "devices/canopen/pdo.h"

#include <QCanBusDevice>
#include <QObject>
#include <QSocketNotifier>
#include <QThread>
#include <QTimer>

#include <array>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

namespace cutcell::canopen {

enum class StartupPhase : std::uint8_t { Idle, WaitBoot, Sdo, WaitOperational, Running, Failed };

struct SdoOp {
    SdoWrite write; // for an upload, write.size == 0 and value unused
    bool upload = false;
};

struct NodeRuntime { // [master]
    StartupPhase phase = StartupPhase::Idle;
    std::vector<SdoOp> ops;
    size_t op = 0;
    int retries = 0;
    std::int64_t deadline_ns = 0;
    // Fault reset requests (NodeShared::fault_reset_requests) have two readers on this
    // thread, each with its own mark: the controlword's rising edge to the drive (the cycle,
    // seen_resets) and the clearing of a master-side fault (onWake, cleared_resets). With one
    // mark, a SYNC due between the request and its wake-up took the request for the
    // controlword and the master's fault stayed: the drive reset, the axis still in Fault.
    std::uint32_t seen_resets = 0;
    std::uint32_t cleared_resets = 0;
    int reset_phase = 0; // 1: send bit 7 low, 2: send bit 7 high (the rising edge)
    std::int32_t previous_actual = 0;
    bool was_enabled = false;
    bool emcy_fault = false;      // master_fault holds an EMCY's error code
    std::uint64_t tpdo_cycle = 0; // last cycle a TPDO was counted for
    // Drives: the engine's write_seq of each SYNC sent and not answered yet, oldest first. A
    // node answers every SYNC once, in order (TPDO1 synchronous type 1), so its next TPDO
    // answers the oldest: after a stall of this thread, frames queued behind a SYNC sent on
    // waking still get the SYNC they answered, not the newest.
    static constexpr int kMaxUnanswered = 16; // more: the oldest are taken as lost
    std::array<std::uint64_t, kMaxUnanswered> unanswered{};
    int unansweredHead = 0, unansweredCount = 0;
    std::uint64_t sync_seq = 0; // the write_seq of the last SYNC sent
    void syncSent(std::uint64_t seq) {
        sync_seq = seq;
        if (unansweredCount == kMaxUnanswered) {
            unansweredHead = (unansweredHead + 1) % kMaxUnanswered;
            --unansweredCount;
        }
        unanswered[static_cast<size_t>((unansweredHead + unansweredCount) % kMaxUnanswered)] = seq;
        ++unansweredCount;
    }
    std::uint64_t answered() { // the SYNC a TPDO just received answers
        if (unansweredCount == 0) return sync_seq;
        const std::uint64_t seq = unanswered[static_cast<size_t>(unansweredHead)];
        unansweredHead = (unansweredHead + 1) % kMaxUnanswered;
        --unansweredCount;
        return seq;
    }
    std::int64_t awaiting_since_ns = 0; // the oldest SYNC not answered yet (0: none)
};

struct CanOpenMaster::Impl {
    CanOpenMasterConfig cfg;
    std::deque<NodeShared> shared;
    std::vector<std::unique_ptr<CanOpenDrive>> drives;     // the drive nodes, in config order
    std::vector<std::unique_ptr<CanOpenEncoder>> encoders; // the encoder nodes, in config order
    std::vector<double> countsPerAxisUnit;                 // per node (counts per rad or mm)
    std::int64_t pdoTimeoutNs = 100'000'000;               // encoders: max(100 ms, 10 cycles)
    std::vector<NodeRuntime> rt;                           // [master]
    int wakeFd = -1;                                       // commands and urgent stops
    int syncFd = -1;                                       // one count per cycle to run
    size_t clockNode = 0; // the drive whose writes post SYNC (nodes.size(): none)
    std::int64_t heartbeatTimeoutNs = 0;
    std::uint16_t heartbeatProducerMs = 100;
    double load = 0;
    std::string loadText;

    std::unique_ptr<QThread> thread;
    QObject* context = nullptr;              // lives on the master thread
    QCanBusDevice* device = nullptr;         // [master]
    QSocketNotifier* wakeNotifier = nullptr; // [master]
    QSocketNotifier* syncNotifier = nullptr; // [master]
    QTimer* housekeeping = nullptr;          // [master]
    std::thread pacer;
    std::atomic<bool> pacing{false};
    bool stopping = false;               // [master]
    std::int64_t lastSyncNs = 0;         // [master]
    std::int64_t lastHousekeepingNs = 0; // [master]
    bool housekeepingDeferred = false;   // [master] the last round judged no deadline
    std::uint8_t syncCounter = 0;        // [master] the last SYNC's counter (0x1019); 0: none yet
    std::uint8_t syncOverflow() const {
        return static_cast<std::uint8_t>(cfg.sync_counter_overflow >= 2 &&
                                                 cfg.sync_counter_overflow <= 240
                                             ? cfg.sync_counter_overflow
                                             : 0);
    }
    // Listening before taking the bus [master]: what another master would send.
    bool listening = false;
    std::int64_t listenUntilNs = 0;
    int heardSync = 0, heardNmt = 0, heardMasterHeartbeat = 0;
    std::string heardNmtText;
    bool busTaken = false;                        // [master] listening found the bus free
    std::int64_t nextMasterHeartbeatNs = 0;       // [master]
    std::function<void(const MasterEvent&)> sink; // set before start()

    std::atomic<std::uint64_t> cycles{0};
    std::atomic<std::uint64_t> completed{0};
    std::atomic<std::uint64_t> framesTx{0};
    std::atomic<std::uint64_t> framesRx{0};
    std::atomic<std::int64_t> lastUrgentNs{0};
    std::atomic<std::uint64_t> lastUrgentCycle{0};

    mutable std::mutex mutex; // guards the fields below (texts, events, jitter ring, bus)
    std::condition_variable changed;
    bool connected = false;
    bool taken = false; // connected and the bus found free: the nodes are being started
    bool connectFailed = false;
    std::string connectError;
    BusState bus = BusState::Unknown;
    std::string busText;
    std::vector<std::string> faultText; // per node
    std::vector<std::string> emcyText;  // per node
    std::deque<MasterEvent> events;
    std::vector<double> jitterUs; // ring of |interval - period|
    size_t jitterNext = 0;

    // canopen_master.cpp
    void event(int node, bool error, const std::string& text);
    void setFault(size_t i, std::uint32_t code, const std::string& text);
    // master_io.cpp (master thread)
    void openDevice();
    void closeDevice();
    void onFrames();
    void onFrame(const CanFrame& f, std::int64_t now);
    void noteCycleAnswer(size_t i);
    std::uint64_t cycleTarget(size_t i);
    void onErrorFrame(std::uint32_t errorClass, const QByteArray& payload);
    void onStateChanged(QCanBusDevice::CanBusDeviceState s);
    void onWake();
    void onSyncDue();
    void runCycle(std::int64_t now);
    void onHousekeeping();
    void startNode(size_t i, std::int64_t now);
    void nextSdo(size_t i, std::int64_t now);
    void onSdoReply(size_t i, const CanFrame& f, std::int64_t now);
    void onBusDown(BusState s, std::uint32_t code, const std::string& why);
    void listenFor(const CanFrame& f);
    void onSecondMaster(const std::string& heard);
    void endListening(std::int64_t now);
    void produceHeartbeat(std::int64_t now);
    void writeDisableAll();
    std::uint16_t controlwordFor(size_t i);
    bool send(const CanFrame& f);
};

std::int64_t steadyNs();

} // namespace cutcell::canopen
