// The simulated CiA 402 slave, frames in and frames out (no bus).
#include "core/job/default_job.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "devices/canopen/drive_node.h"
#include "devices/canopen/emcy.h"
#include "devices/canopen/pdo.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace cutcell;
using namespace cutcell::canopen;

namespace {

constexpr int kNode = 4;

DriveNodeConfig config() {
    const Job job = defaultJob();
    DriveNodeConfig c;
    c.node = kNode;
    c.gains = cutcell::pipeRobotSpec(job).controller[1];
    c.plant = cutcell::pipeRobotSpec(job).plant[1];
    c.counts_per_rad = countsPerRad(job.devices.counts_per_unit[1], false);
    return c;
}

struct Bench {
    DriveNode node;
    double now = 0;
    std::vector<CanFrame> out;
    std::uint8_t syncOverflow = 0, syncCounter = 0; // 0x1019 as configured, the last counter

    explicit Bench(const DriveNodeConfig& c) : node(c) { node.boot(0, out); }

    std::vector<CanFrame> send(const CanFrame& f) {
        out.clear();
        node.handle(f, now, out);
        return out;
    }
    SdoMessage sdo(const CanFrame& request) {
        const auto replies = send(request);
        EXPECT_EQ(replies.size(), 1u);
        return replies.empty() ? SdoMessage{} : decodeSdo(replies.front());
    }
    void configure(std::uint32_t cycleUs = 2000, std::uint8_t overflow = 0) {
        DriveConfig dc;
        dc.cycle_period_us = cycleUs;
        dc.sync_counter_overflow = overflow;
        syncOverflow = overflow;
        for (const SdoWrite& w : cspStartupWrites(kNode, dc)) {
            const SdoMessage m = sdo(sdoDownloadRequest(kNode, w.address, w.value, w.size));
            ASSERT_EQ(m.kind, SdoKind::DownloadResponse)
                << std::hex << w.address.index << ":" << int(w.address.sub) << " "
                << sdoAbortText(m.value);
        }
        send(encodeNmt(NmtCommand::Start, 0));
    }
    // One cycle: RPDO1 then SYNC; returns the TPDO sampled at the SYNC.
    Tpdo1 cycle(std::uint16_t cw, std::int32_t target) {
        send(encodeRpdo1(kNode, {cw, target}));
        now += 0.002;
        Tpdo1 t;
        if (syncOverflow > 0) syncCounter = nextSyncCounter(syncCounter, syncOverflow);
        for (const CanFrame& f : send(encodeSync(syncCounter)))
            if (decodeTpdo1(f, t)) return t;
        ADD_FAILURE() << "no TPDO after SYNC";
        return t;
    }
    Tpdo1 enable() {
        Tpdo1 t = cycle(0, 0);
        for (int i = 0; i < 5 && decodeStatusword(t.statusword) != Cia402State::OperationEnabled;
             ++i)
            t = cycle(
                controlwordToward(decodeStatusword(t.statusword), DriveGoal::OperationEnabled),
                t.actual_counts);
        t = cycle(cw::kEnableOperation, t.actual_counts);
        return t;
    }
};

} // namespace

TEST(DriveNode, BootsAndAnswersIdentity) {
    Bench b(config());
    ASSERT_EQ(b.out.size(), 1u);
    int node = 0;
    NmtState s;
    ASSERT_TRUE(decodeHeartbeat(b.out[0], node, s));
    EXPECT_EQ(s, NmtState::BootUp);
    EXPECT_EQ(b.node.nmtState(), NmtState::PreOperational);
    const SdoMessage m = b.sdo(sdoUploadRequest(kNode, {od::kDeviceType, 0}));
    EXPECT_EQ(m.kind, SdoKind::UploadResponse);
    EXPECT_EQ(m.value, od::kDeviceTypeCia402);
}

TEST(DriveNode, WrongAccessesGiveCia301Aborts) {
    Bench b(config());
    struct Row {
        CanFrame request;
        std::uint32_t abort;
    };
    const Row rows[] = {
        {sdoUploadRequest(kNode, {0x2000, 0}), abort_code::kNoObject},
        {sdoUploadRequest(kNode, {od::kStatusword, 3}), abort_code::kNoSubIndex},
        {sdoDownloadRequest(kNode, {od::kStatusword, 0}, 0, 2), abort_code::kReadOnly},
        {sdoDownloadRequest(kNode, {od::kModesOfOperation, 0}, 1, 1), abort_code::kInvalidValue},
        {sdoDownloadRequest(kNode, {od::kControlword, 0}, 6, 4), abort_code::kLengthMismatch},
        {sdoDownloadRequest(kNode, {od::kCommCyclePeriod, 0}, 10, 4), abort_code::kValueTooLow},
        // Mapping a valid PDO is refused; mapping a TPDO object into an RPDO too.
        {sdoDownloadRequest(kNode, {od::kRpdoMap, 1}, mapEntry(od::kControlword, 0, 16), 4),
         abort_code::kDeviceState},
    };
    for (const Row& r : rows) {
        const SdoMessage m = b.sdo(r.request);
        EXPECT_EQ(m.kind, SdoKind::Abort);
        EXPECT_EQ(m.value, r.abort)
            << sdoAbortText(m.value) << " instead of " << sdoAbortText(r.abort);
    }
    b.sdo(sdoDownloadRequest(kNode, {od::kRpdoComm, 1}, kCobIdInvalid | 0x204, 4));
    b.sdo(sdoDownloadRequest(kNode, {od::kRpdoMap, 0}, 0, 1));
    const SdoMessage m =
        b.sdo(sdoDownloadRequest(kNode, {od::kRpdoMap, 1}, mapEntry(od::kStatusword, 0, 16), 4));
    EXPECT_EQ(m.value, abort_code::kCannotMap);
}

TEST(DriveNode, EnablesAndFollowsCspTargetWithoutJump) {
    DriveNodeConfig c = config();
    c.start_position_rad = 0.3;
    Bench b(c);
    b.configure();
    const Tpdo1 t = b.enable();
    ASSERT_EQ(decodeStatusword(t.statusword), Cia402State::OperationEnabled);
    // Enabling held the actual position: no jump.
    EXPECT_NEAR(b.node.positionRad(), 0.3, 1 / c.counts_per_rad); // within one count
    // A slow ramp of the target is followed within a small error.
    const double cpr = c.counts_per_rad;
    double target = 0.3;
    Tpdo1 last = t;
    for (int k = 0; k < 500; ++k) {
        target += 0.1 * 0.002; // 0.1 rad/s
        last = b.cycle(cw::kEnableOperation, static_cast<std::int32_t>(std::lround(target * cpr)));
    }
    EXPECT_EQ(decodeStatusword(last.statusword), Cia402State::OperationEnabled);
    // The TPDO at SYNC k reports the position the target of SYNC k-1 asked for.
    EXPECT_NEAR(last.actual_counts / cpr, target - 0.1 * 0.002, 0.002);
}

TEST(DriveNode, QuickStopOnAsyncRpdoActsAtOnceThenDisables) {
    Bench b(config());
    b.configure();
    b.enable();
    b.send(encodeRpdo2(kNode, cw::kQuickStop)); // no SYNC needed
    EXPECT_EQ(b.node.driveState(), Cia402State::QuickStopActive);
    for (int i = 0; i < 50 && b.node.driveState() == Cia402State::QuickStopActive; ++i)
        b.cycle(cw::kQuickStop, 0);
    EXPECT_EQ(b.node.driveState(), Cia402State::SwitchOnDisabled);
}

TEST(DriveNode, InjectedFaultSendsEmcyAndResetsOnRisingEdge) {
    DriveNodeConfig c = config();
    c.faults.fault_code = emcy_code::kDriveOverTemperature;
    c.faults.fault_after_s = 0.01;
    Bench b(c);
    b.configure();
    b.enable();
    Emcy e;
    bool sawEmcy = false;
    for (int i = 0; i < 20 && !sawEmcy; ++i) {
        b.cycle(cw::kEnableOperation, 0);
        for (const CanFrame& f : b.out) {
            sawEmcy = sawEmcy || decodeEmcy(f, e);
        }
    }
    ASSERT_TRUE(sawEmcy);
    EXPECT_EQ(e.error_code, emcy_code::kDriveOverTemperature);
    EXPECT_EQ(b.node.driveState(), Cia402State::Fault);
    b.cycle(cw::kFaultResetBit,
            0); // reset bit high without a rising edge (prev was 0x0F... then 0x80)
    EXPECT_EQ(b.node.driveState(), Cia402State::SwitchOnDisabled);
    b.cycle(cw::kFaultResetBit, 0);
    EXPECT_EQ(b.node.driveState(), Cia402State::SwitchOnDisabled);
}

TEST(DriveNode, TorqueLossEndsInFollowingErrorFault) {
    DriveNodeConfig c = config();
    c.faults.torque_loss_after_s = 0.0;
    Bench b(c);
    b.configure();
    b.enable();
    double target = 0;
    for (int k = 0; k < 2000 && b.node.driveState() == Cia402State::OperationEnabled; ++k) {
        target += 1.0 * 0.002;
        b.cycle(cw::kEnableOperation,
                static_cast<std::int32_t>(std::lround(target * c.counts_per_rad)));
    }
    EXPECT_EQ(b.node.driveState(), Cia402State::Fault);
    EXPECT_EQ(b.node.errorCode(), emcy_code::kFollowingError);
}

TEST(DriveNode, HeartbeatProducedAndStoppedByInjection) {
    DriveNodeConfig c = config();
    c.faults.heartbeat_stop_after_s = 0.5;
    Bench b(c);
    b.configure(); // sets 0x1017 = 100 ms, NMT start at t = 0
    int beats = 0;
    for (int i = 0; i < 100; ++i) {
        b.now += 0.01;
        b.out.clear();
        b.node.tick(b.now, b.out);
        for (const CanFrame& f : b.out) {
            int n;
            NmtState s;
            if (decodeHeartbeat(f, n, s)) {
                ++beats;
                EXPECT_EQ(s, NmtState::Operational);
                EXPECT_LT(b.now, 0.5 + 1e-9);
            }
        }
    }
    EXPECT_GE(beats, 4);
}

// The drive watches the master (0x1016 consumer, 0x6007 reaction): when the master's heartbeat
// stops for longer than the configured time, an enabled drive signals EMCY 0x8130, quick-stops
// out of Operation Enabled and leaves Operational. Not before the time, and not before the
// master's first heartbeat (the consumer arms on it).
TEST(DriveNode, LosingTheMastersHeartbeatQuickStopsTheDrive) {
    constexpr int kMaster = 127;
    constexpr std::uint16_t kTimeoutMs = 300;
    Bench b(config());
    DriveConfig dc;
    dc.cycle_period_us = 2000;
    dc.master_node = kMaster;
    dc.master_heartbeat_timeout_ms = kTimeoutMs;
    dc.abort_connection_option = abort_connection::kQuickStop;
    for (const SdoWrite& w : cspStartupWrites(kNode, dc)) {
        const SdoMessage m = b.sdo(sdoDownloadRequest(kNode, w.address, w.value, w.size));
        ASSERT_EQ(m.kind, SdoKind::DownloadResponse)
            << std::hex << w.address.index << ":" << int(w.address.sub) << " "
            << sdoAbortText(m.value);
    }
    const SdoMessage consumer = b.sdo(sdoUploadRequest(kNode, {od::kConsumerHeartbeat, 1}));
    EXPECT_EQ(consumer.value, (std::uint32_t(kMaster) << 16) | kTimeoutMs);
    EXPECT_EQ(b.sdo(sdoUploadRequest(kNode, {od::kAbortConnectionOption, 0})).value, 3u);
    b.send(encodeNmt(NmtCommand::Start, 0));
    b.send(encodeHeartbeat(kMaster, NmtState::Operational));
    const double lastHeartbeat = b.now;
    ASSERT_EQ(decodeStatusword(b.enable().statusword), Cia402State::OperationEnabled);
    // Keep cycling (SYNCs keep coming: only the heartbeat is missing) past the timeout.
    std::vector<CanFrame> emcys;
    double leftAt = -1;
    while (b.now < lastHeartbeat + 0.6) {
        b.now += 0.002;
        std::vector<CanFrame> out;
        if (b.node.nmtState() == NmtState::Operational) {
            b.send(encodeRpdo1(kNode, {cw::kEnableOperation, 0}));
            out = b.send(encodeSync()); // a SYNC also runs the drive's periodic work
        } else {
            b.node.tick(b.now, out);
        }
        for (const CanFrame& f : out) {
            Emcy e;
            if (decodeEmcy(f, e)) emcys.push_back(f);
        }
        if (leftAt < 0 && b.node.driveState() != Cia402State::OperationEnabled) leftAt = b.now;
    }
    ASSERT_GT(leftAt, 0) << "the drive stayed in Operation Enabled without the master";
    EXPECT_GE(leftAt - lastHeartbeat, kTimeoutMs * 1e-3);
    EXPECT_LE(leftAt - lastHeartbeat, kTimeoutMs * 1e-3 + 0.002 + 1e-9); // at the next cycle
    ASSERT_EQ(emcys.size(), 1u);
    Emcy e;
    ASSERT_TRUE(decodeEmcy(emcys[0], e));
    EXPECT_EQ(e.error_code, emcy_code::kHeartbeat);
    EXPECT_EQ(b.node.nmtState(), NmtState::PreOperational);
    EXPECT_NE(b.node.driveState(), Cia402State::OperationEnabled);
}

TEST(DriveNode, WithoutAMasterHeartbeatYetTheConsumerWaits) {
    Bench b(config());
    DriveConfig dc;
    dc.master_node = 127;
    dc.master_heartbeat_timeout_ms = 100;
    dc.abort_connection_option = abort_connection::kFault;
    for (const SdoWrite& w : cspStartupWrites(kNode, dc))
        b.sdo(sdoDownloadRequest(kNode, w.address, w.value, w.size));
    b.send(encodeNmt(NmtCommand::Start, 0));
    ASSERT_EQ(decodeStatusword(b.enable().statusword), Cia402State::OperationEnabled);
    for (int i = 0; i < 200; ++i) // 0.4 s of cycles, no master heartbeat ever
        b.cycle(cw::kEnableOperation, 0);
    EXPECT_EQ(b.node.driveState(), Cia402State::OperationEnabled);
    // 0x6007 takes 0..3 only; 0x1016 a producer id up to 127.
    EXPECT_EQ(b.sdo(sdoDownloadRequest(kNode, {od::kAbortConnectionOption, 0}, 4, 2)).value,
              abort_code::kInvalidValue);
    EXPECT_EQ(
        b.sdo(sdoDownloadRequest(kNode, {od::kConsumerHeartbeat, 1}, (200u << 16) | 100, 4)).value,
        abort_code::kInvalidValue);
}

// NMT reset communication (from anyone: the master, a second master, a tool) takes the node
// out of Operational: an enabled drive stops itself instead of holding torque while nobody
// commands it (issue 27: such a node stayed enabled 20-25 s).
TEST(DriveNode, ResetCommunicationWhileEnabledStopsTheDrive) {
    for (const NmtCommand c : {NmtCommand::ResetCommunication, NmtCommand::EnterPreOperational,
                               NmtCommand::Stop, NmtCommand::ResetNode}) {
        Bench b(config());
        b.configure();
        ASSERT_EQ(decodeStatusword(b.enable().statusword), Cia402State::OperationEnabled);
        const std::vector<CanFrame> out = b.send(encodeNmt(c, kNode));
        EXPECT_NE(b.node.driveState(), Cia402State::OperationEnabled) << toString(c);
        EXPECT_NE(b.node.nmtState(), NmtState::Operational) << toString(c);
        if (c == NmtCommand::ResetCommunication || c == NmtCommand::ResetNode) {
            int node = 0;
            NmtState s;
            ASSERT_FALSE(out.empty());
            EXPECT_TRUE(decodeHeartbeat(out.back(), node, s) && s == NmtState::BootUp);
        }
        // Without SYNCs the drive's own loop finishes the stop.
        for (int i = 0; i < 200 && b.node.driveState() == Cia402State::QuickStopActive; ++i) {
            b.now += 0.002;
            std::vector<CanFrame> ignored;
            b.node.tick(b.now, ignored);
        }
        EXPECT_NE(b.node.driveState(), Cia402State::QuickStopActive) << toString(c);
    }
}

// Issue 27: with 0x1019 set the SYNC carries a counter 1..overflow and the drive checks that it
// advances by one: the wrap from the overflow to 1 is in sequence; a skipped counter (a second
// SYNC producer, a lost SYNC) is a communication error - EMCY 0x8100, the 0x6007 reaction (quick
// stop), out of Operational - and that SYNC moves nothing. A SYNC without the counter's byte is
// EMCY 0x8240.
TEST(DriveNode, ASkippedSyncCounterStopsTheDrive) {
    Bench b(config());
    b.configure(2000, 5);
    EXPECT_EQ(b.sdo(sdoUploadRequest(kNode, {od::kSyncCounterOverflow, 0})).value, 5u);
    EXPECT_EQ(b.sdo(sdoDownloadRequest(kNode, {od::kSyncCounterOverflow, 0}, 1, 1)).kind,
              SdoKind::Abort); // 1 is reserved
    ASSERT_EQ(decodeStatusword(b.enable().statusword), Cia402State::OperationEnabled);
    for (int i = 0; i < 12; ++i) // through two wraps 5 -> 1
        ASSERT_EQ(decodeStatusword(b.cycle(cw::kEnableOperation, 0).statusword),
                  Cia402State::OperationEnabled)
            << "counter " << int(b.syncCounter);
    const std::uint64_t syncs = b.node.syncCount();
    b.now += 0.002;
    const std::uint8_t skipped = nextSyncCounter(nextSyncCounter(b.syncCounter, 5), 5);
    bool communication = false;
    for (const CanFrame& f : b.send(encodeSync(skipped))) {
        Emcy e;
        communication = communication || (decodeEmcy(f, e) && e.error_code == 0x8100);
    }
    EXPECT_TRUE(communication);
    EXPECT_NE(b.node.driveState(), Cia402State::OperationEnabled);
    EXPECT_NE(b.node.nmtState(), NmtState::Operational);
    EXPECT_EQ(b.node.syncCount(), syncs); // the skipped SYNC moved nothing

    Bench c(config());
    c.configure(2000, 5);
    ASSERT_EQ(decodeStatusword(c.enable().statusword), Cia402State::OperationEnabled);
    bool length = false;
    for (const CanFrame& f : c.send(encodeSync())) {
        Emcy e;
        length = length || (decodeEmcy(f, e) && e.error_code == 0x8240);
    }
    EXPECT_TRUE(length);
    EXPECT_NE(c.node.driveState(), Cia402State::OperationEnabled);
}
