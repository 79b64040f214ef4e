#pragma once
// CANopen master for CiA 402 drives in cyclic synchronous position mode (CSP) over Qt
// SerialBus (socketcan on a real bus, virtualcan in tests).
//
// What it does: checks the bus load of the cycle and that the plugin offers the interface;
// connects; listens before it takes the bus and refuses to start when another master is
// active (SYNC, NMT command or a master heartbeat heard); produces its own heartbeat
// (0x700 + master_node_id, the drives' period); per node: NMT reset
// communication, waits for the boot-up, checks the device type, configures CSP, the cycle
// period, RPDO1/RPDO2/TPDO1, the heartbeat, the abort connection option (0x6007) and the
// consumer of the master's heartbeat (0x1016) by expedited SDO, NMT start; then per cycle
// sends RPDO1 (controlword + target) to every node followed by SYNC; consumes TPDOs,
// heartbeats (timeout -> Fault) and EMCYs (decoded, logged, shown); watches the bus state.
// Drives may run in CST instead (0x6060 = 10, RPDO1 = controlword + target torque 0x6071, the
// rated torque 0x6076 read at start-up); CiA 406 encoders on the same bus are configured
// (device type 406, TPDO1 = position value 0x6004 on every SYNC, heartbeat) and read as
// sensors (CanOpenEncoder): a SYNC an encoder leaves unanswered for max(100 ms, 10 cycles) is
// a fault of that node ("no position value (TPDO) ..."), as is its heartbeat's loss.
//
// SYNC source (a choice, see the note in canopen_master.cpp):
//  - SyncSource::Internal: a pacing thread with absolute-time sleeps (clock_nanosleep) wakes
//    the master thread each period through an eventfd; measured jitter in stats();
//  - SyncSource::External: the caller (a lock-step runner) calls sync() once per cycle;
//  - SyncSource::LastDriveWrite: the write() of the last drive posts the cycle, so the SYNC
//    follows the engine's own real-time clock right after it wrote every set-point (the
//    engine writes every axis once per cycle). Use this with the motion engine.
//
// Threading contract:
//  - The master runs on its own QThread with its own event loop; the QCanBusDevice lives and
//    is used there only.
//  - drive(i) objects are used by the engine thread: read()/write()/commands touch atomics
//    and an eventfd only (never block, lock or allocate).
//  - sync() and emergencyStop() may be called from any thread, never block.
//  - start()/stop() from one controlling thread; start() waits (bounded) for the connection
//    and the listening before taking the bus (running the calling thread's events meanwhile:
//    it may host the virtualcan bus), not for the nodes: poll allOperational() (while running
//    your event loop if this thread hosts a virtualcan bus).
//  - snapshot()/drainEvents()/stats() from any thread (short mutex; not for a control cycle).
#include "core/devices/device_interfaces.h"
#include "devices/canopen/bus_state.h"
#include "devices/canopen/canopen_drive.h"
#include "devices/canopen/canopen_encoder.h"
#include "devices/canopen/cia402.h"
#include "devices/canopen/nmt.h"

#include <QString>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace cutcell {
struct Job;
}

namespace cutcell::canopen {

enum class SyncSource : std::uint8_t { Internal, External, LastDriveWrite };

struct MasterNodeConfig {
    int node = 1;
    double counts_per_unit = 1000; // per deg (rotary) or per mm (linear)
    bool linear = false;
    // A CiA 402 drive in CSP (target position) or CST (target torque); or a CiA 406 encoder
    // (a sensor: TPDO1 = position value 0x6004, no RPDO).
    AxisCommandMode mode = AxisCommandMode::Position;
    bool encoder = false;
};

struct CanOpenMasterConfig {
    QString plugin = QStringLiteral("virtualcan");
    QString interface = QStringLiteral("can0");
    int bitrate_bps = 1000000;
    double period_s = 0.004;
    std::vector<MasterNodeConfig> nodes;
    double heartbeat_timeout_s = 0.3; // consumer; nodes produce every timeout / 3
    SyncSource sync = SyncSource::Internal;
    int sdo_timeout_ms = 100;
    int sdo_retries = 2;
    int boot_timeout_ms = 1000;
    double bus_load_limit = 0.8;
    // The master's own node id: its heartbeat (0x700 + id, produced at the drives' period) is
    // what the drives watch; each drive reacts to its loss after heartbeat_timeout_s with
    // abort_connection_option (0x6007, CiA 402: 3 = quick stop). 0: no master heartbeat.
    int master_node_id = 127;
    int abort_connection_option = 3;
    // Listen this long after connecting before taking the bus: another master (SYNC, NMT or a
    // heartbeat from master_node_id heard) makes start() fail, naming what was heard.
    int listen_before_start_ms = 250;
    // CiA 301 0x1019 (0, or 2..240): written to every node; the SYNC then carries a counter
    // 1..overflow that the drives check (a skipped or repeated one is a communication error).
    int sync_counter_overflow = 240;
};

// From a job's devices section (plugin, interface, bit rate, node ids, scaling, heartbeat),
// with period_s as the cycle; axes beyond axisCount are left out (all rotary CSP drives: the
// pipe robot's; other machines set each node's unit, mode and their encoders after it).
CanOpenMasterConfig masterConfigFromJob(const Job& job, double period_s, int axisCount);

struct CanNodeSnapshot {
    int node = 0;
    NmtState nmt = NmtState::Unknown;
    Cia402State state = Cia402State::Unknown;
    std::uint16_t statusword = 0;
    double position = 0; // axis units (rad or mm)
    bool configured = false;
    double heartbeat_age_ms = -1; // -1: none yet
    std::uint16_t last_emcy_code = 0;
    std::string last_emcy_text; // empty when none
    std::uint32_t fault_code = 0;
    std::string
        fault_text; // the master-side reason, e.g. "heartbeat lost (none for 312 ms > 300 ms)"
};

struct CanBusSnapshot {
    BusState bus = BusState::Unknown;
    std::string bus_text;
    double load = 0; // computed worst-case fraction of the bit rate
    std::string load_text;
    std::vector<CanNodeSnapshot> nodes;
};

struct MasterEvent {
    std::int64_t wall_ms = 0;
    int node = 0; // 0 = the bus
    bool error = false;
    std::string text;
};

struct MasterStats {
    std::uint64_t cycles = 0;           // SYNCs sent
    std::uint64_t completed_cycles = 0; // SYNCs whose TPDOs all arrived
    std::uint64_t frames_tx = 0;
    std::uint64_t frames_rx = 0;
    double sync_jitter_us_p50 = 0; // |SYNC interval - period| over the last 4096 cycles
    double sync_jitter_us_p99 = 0;
    double sync_jitter_us_max = 0;
    std::int64_t last_urgent_ns = 0;     // steady clock when the last urgent frame was written
    std::uint64_t last_urgent_cycle = 0; // SYNCs sent before the last urgent frame was written
};

class CanOpenMaster {
  public:
    explicit CanOpenMaster(CanOpenMasterConfig config);
    ~CanOpenMaster();
    CanOpenMaster(const CanOpenMaster&) = delete;
    CanOpenMaster& operator=(const CanOpenMaster&) = delete;

    // What start() checks before it touches the bus (nodes configured, bus load within the
    // limit, plugin installed and offering the interface): false with the reason. Any thread.
    bool checkConfig(std::string* error) const;
    // False with the reason (checkConfig's, another master on the bus, no connection within
    // timeout_ms). May be called again after stop(): each start begins afresh (the nodes'
    // master-side faults, EMCY texts and states of the previous connection are cleared).
    bool start(std::string* error, int timeout_ms = 3000);
    // Disables every drive (controlword disable voltage on RPDO2, then NMT pre-operational to
    // all), flushes the frames to the bus and closes. Any one controlling thread.
    void stop();
    // Safe state now, from any thread: disable voltage to every node at once and NMT
    // pre-operational, written and flushed on the master thread; waits at most timeout_ms for
    // that (never for the drives). True when the frames were written.
    bool disableAllNow(int timeout_ms = 200);

    // Called on the master thread for every event (after it is queued for drainEvents()), e.g.
    // to put it into the run log at once. Set before start().
    void setEventSink(std::function<void(const MasterEvent&)> sink);

    // The drives (config order, encoders left out) and the encoders (config order).
    int driveCount() const;
    CanOpenDrive* drive(int i);
    int encoderCount() const;
    CanOpenEncoder* encoder(int i);

    bool allOperational() const;           // every node configured and reporting Operational
    void sync();                           // External source: one cycle now
    std::uint64_t cyclesSent() const;      // SYNCs written so far
    std::uint64_t cyclesCompleted() const; // last SYNC whose TPDOs all arrived
    // Every node at once, not waiting for a SYNC: quick stop (category 1) or disable voltage
    // (category 0), on the asynchronous RPDO2.
    void emergencyStop(bool disableVoltage);
    // Clears the bus fault: reconnects the device and configures the nodes again.
    void recoverBus();

    CanBusSnapshot snapshot() const;
    std::vector<MasterEvent> drainEvents();
    MasterStats stats() const;
    void resetJitter(); // start the SYNC jitter figures afresh (e.g. after start-up)
    std::string loadText() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace cutcell::canopen
