// Table tests of the CANopen codec against the CiA 301 / CiA 402 tables.
#include "devices/canopen/cia402.h"
#include "devices/canopen/emcy.h"
#include "devices/canopen/nmt.h"
#include "devices/canopen/pdo.h"
#include "devices/canopen/sdo.h"

#include <gtest/gtest.h>

using namespace cutcell::canopen;

namespace {

struct StatusRow {
    std::uint16_t statusword;
    Cia402State state;
};

// CiA 402 statusword table, with the "don't care" bits (4 voltage enabled, 7 warning,
// 9 remote, 10 target reached, 13 following error) set in some rows.
const StatusRow kStatusRows[] = {
    {0x0000, Cia402State::NotReadyToSwitchOn},
    {0x0020, Cia402State::NotReadyToSwitchOn}, // bit 5 free in this state
    {0x0040, Cia402State::SwitchOnDisabled},
    {0x0260, Cia402State::SwitchOnDisabled},
    {0x0021, Cia402State::ReadyToSwitchOn},
    {0x0231, Cia402State::ReadyToSwitchOn},
    {0x0023, Cia402State::SwitchedOn},
    {0x0027, Cia402State::OperationEnabled},
    {0x2637, Cia402State::OperationEnabled},
    {0x0007, Cia402State::QuickStopActive},
    {0x0217, Cia402State::QuickStopActive},
    {0x000F, Cia402State::FaultReactionActive},
    {0x002F, Cia402State::FaultReactionActive},
    {0x0008, Cia402State::Fault},
    {0x0228, Cia402State::Fault},
    {0x0001, Cia402State::Unknown}, // ready without quick-stop bit: not in the table
};

} // namespace

TEST(Cia402, StatuswordDecodesPerTable) {
    for (const StatusRow& r : kStatusRows)
        EXPECT_EQ(decodeStatusword(r.statusword), r.state)
            << "statusword 0x" << std::hex << r.statusword;
}

TEST(Cia402, StatuswordEncodeDecodeRoundTrip) {
    for (auto s :
         {Cia402State::NotReadyToSwitchOn, Cia402State::SwitchOnDisabled,
          Cia402State::ReadyToSwitchOn, Cia402State::SwitchedOn, Cia402State::OperationEnabled,
          Cia402State::QuickStopActive, Cia402State::FaultReactionActive, Cia402State::Fault}) {
        EXPECT_EQ(decodeStatusword(encodeStatusword(s)), s) << toString(s);
        // Extra status bits never change the state.
        EXPECT_EQ(decodeStatusword(encodeStatusword(s) | sw::kVoltageEnabled | sw::kRemote |
                                   sw::kWarning | sw::kTargetReached | sw::kFollowingError),
                  s)
            << toString(s);
    }
}

TEST(Cia402, ControlwordCommandsPerTable) {
    struct Row {
        Cia402State from;
        std::uint16_t cw;
        Cia402State to;
    };
    using S = Cia402State;
    const Row rows[] = {
        {S::SwitchOnDisabled, 0x0006, S::ReadyToSwitchOn},  // 2 shutdown
        {S::ReadyToSwitchOn, 0x0007, S::SwitchedOn},        // 3 switch on
        {S::SwitchedOn, 0x000F, S::OperationEnabled},       // 4 enable operation
        {S::OperationEnabled, 0x0007, S::SwitchedOn},       // 5 disable operation
        {S::SwitchedOn, 0x0006, S::ReadyToSwitchOn},        // 6 shutdown
        {S::ReadyToSwitchOn, 0x0000, S::SwitchOnDisabled},  // 7 disable voltage
        {S::ReadyToSwitchOn, 0x0002, S::SwitchOnDisabled},  // 7 quick stop
        {S::OperationEnabled, 0x0006, S::ReadyToSwitchOn},  // 8 shutdown
        {S::OperationEnabled, 0x0000, S::SwitchOnDisabled}, // 9 disable voltage
        {S::SwitchedOn, 0x0000, S::SwitchOnDisabled},       // 10 disable voltage
        {S::SwitchedOn, 0x0002, S::SwitchOnDisabled},       // 10 quick stop
        {S::OperationEnabled, 0x0002, S::QuickStopActive},  // 11 quick stop
        {S::QuickStopActive, 0x0000, S::SwitchOnDisabled},  // 12 disable voltage
        {S::QuickStopActive, 0x000F, S::QuickStopActive},   // 16 not offered (option code 2)
        {S::SwitchOnDisabled, 0x000F, S::SwitchOnDisabled}, // enable needs shutdown first
        {S::OperationEnabled, 0x008F, S::OperationEnabled}, // reset bit outside Fault: nothing
        {S::Fault, 0x000F, S::Fault},                       // no reset bit
    };
    for (const Row& r : rows)
        EXPECT_EQ(applyControlword(r.from, 0, r.cw), r.to)
            << toString(r.from) << " + cw 0x" << std::hex << r.cw;
}

TEST(Cia402, FaultResetActsOnRisingEdgeOnly) {
    EXPECT_EQ(applyControlword(Cia402State::Fault, 0x0000, 0x0080), Cia402State::SwitchOnDisabled);
    EXPECT_EQ(applyControlword(Cia402State::Fault, 0x0080, 0x0080),
              Cia402State::Fault); // held high
    EXPECT_EQ(applyControlword(Cia402State::Fault, 0x0006, 0x0086), Cia402State::SwitchOnDisabled);
}

TEST(Cia402, WalkingTowardGoalsReachesThem) {
    // Property: from every stable state the master's controlwords reach the goal in a few steps.
    using S = Cia402State;
    for (S start : {S::SwitchOnDisabled, S::ReadyToSwitchOn, S::SwitchedOn, S::OperationEnabled}) {
        S s = start;
        std::uint16_t prev = 0;
        for (int i = 0; i < 4 && s != S::OperationEnabled; ++i) {
            const std::uint16_t c = controlwordToward(s, DriveGoal::OperationEnabled);
            s = applyControlword(s, prev, c);
            prev = c;
        }
        EXPECT_EQ(s, S::OperationEnabled) << "from " << toString(start);
        EXPECT_EQ(applyControlword(S::OperationEnabled, prev,
                                   controlwordToward(S::OperationEnabled, DriveGoal::Disabled)),
                  S::SwitchOnDisabled);
        EXPECT_EQ(applyControlword(S::OperationEnabled, prev,
                                   controlwordToward(S::OperationEnabled, DriveGoal::QuickStop)),
                  S::QuickStopActive);
    }
    EXPECT_FALSE(torqueOn(S::SwitchOnDisabled));
    EXPECT_TRUE(torqueOn(S::OperationEnabled));
}

TEST(Sdo, ExpeditedFramesPerCia301) {
    const SdoAddress a{0x6060, 0};
    const CanFrame up = sdoUploadRequest(5, a);
    EXPECT_EQ(up.id, 0x605u);
    EXPECT_EQ(up.len, 8);
    EXPECT_EQ(up.data[0], 0x40);
    EXPECT_EQ(up.data[1], 0x60); // index little endian
    EXPECT_EQ(up.data[2], 0x60);
    // Download command bytes by size: 0x2F (1 byte), 0x2B (2), 0x27 (3), 0x23 (4).
    const std::uint8_t expected[] = {0x2F, 0x2B, 0x27, 0x23};
    for (int size = 1; size <= 4; ++size) {
        const CanFrame d = sdoDownloadRequest(1, {0x1017, 0}, 0xAABBCCDD, size);
        EXPECT_EQ(d.id, 0x601u);
        EXPECT_EQ(d.data[0], expected[size - 1]);
        const SdoMessage m = decodeSdo(d);
        EXPECT_EQ(m.kind, SdoKind::DownloadRequest);
        EXPECT_EQ(m.size, size);
        EXPECT_EQ(m.value, size == 4 ? 0xAABBCCDDu : 0xAABBCCDDu & ((1u << (8 * size)) - 1));
        EXPECT_EQ(m.address, (SdoAddress{0x1017, 0}));
    }
    // Upload response bytes: 0x4F, 0x4B, 0x47, 0x43.
    const std::uint8_t upExpected[] = {0x4F, 0x4B, 0x47, 0x43};
    for (int size = 1; size <= 4; ++size) {
        const CanFrame r = sdoUploadResponse(7, {0x1000, 0}, 0x00020192, size);
        EXPECT_EQ(r.id, 0x587u);
        EXPECT_EQ(r.data[0], upExpected[size - 1]);
        const SdoMessage m = decodeSdo(r);
        EXPECT_EQ(m.kind, SdoKind::UploadResponse);
        EXPECT_EQ(m.size, size);
    }
    const CanFrame ok = sdoDownloadResponse(7, a);
    EXPECT_EQ(ok.data[0], 0x60);
    EXPECT_EQ(decodeSdo(ok).kind, SdoKind::DownloadResponse);
    const CanFrame ab = sdoAbort(7, a, 0x06020000, true);
    EXPECT_EQ(ab.data[0], 0x80);
    EXPECT_EQ(ab.data[4], 0x00);
    EXPECT_EQ(ab.data[7], 0x06); // abort code little endian
    const SdoMessage am = decodeSdo(ab);
    EXPECT_EQ(am.kind, SdoKind::Abort);
    EXPECT_EQ(am.value, 0x06020000u);
}

TEST(Sdo, SegmentedTransfersAreReportedUnsupported) {
    CanFrame f = sdoUploadResponse(1, {0x1008, 0}, 0, 4);
    f.data[0] = 0x41; // segmented upload initiate (size indicated, not expedited)
    EXPECT_EQ(decodeSdo(f).kind, SdoKind::Unsupported);
    f.len = 6;
    EXPECT_EQ(decodeSdo(f).kind, SdoKind::Unsupported);
}

TEST(Sdo, AbortCodesDecodeToText) {
    struct Row {
        std::uint32_t code;
        const char* words;
    };
    const Row rows[] = {
        {0x05040000, "timed out"},
        {0x06010002, "read-only"},
        {0x06020000, "does not exist"},
        {0x06040041, "cannot be mapped"},
        {0x06070010, "length of service parameter does not match"},
        {0x06090011, "sub-index does not exist"},
        {0x06090030, "invalid value"},
        {0x08000022, "present device state"},
    };
    for (const Row& r : rows) {
        const std::string t = sdoAbortText(r.code);
        EXPECT_NE(t.find(r.words), std::string::npos) << t;
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%08X", r.code);
        EXPECT_EQ(t.rfind(hex, 0), 0u) << t;
    }
    EXPECT_NE(sdoAbortText(0x12345678).find("unknown"), std::string::npos);
}

TEST(Emcy, FrameRoundTripAndText) {
    const CanFrame f = encodeEmcy(3, 0x8611, errorRegisterFor(0x8611));
    EXPECT_EQ(f.id, 0x83u);
    EXPECT_EQ(f.len, 8);
    Emcy e;
    ASSERT_TRUE(decodeEmcy(f, e));
    EXPECT_EQ(e.node, 3);
    EXPECT_EQ(e.error_code, 0x8611);
    EXPECT_TRUE(e.error_register & error_register::kGeneric);
    EXPECT_FALSE(decodeEmcy(encodeSync(), e)); // SYNC shares 0x080 but has node 0
    EXPECT_NE(emcyText(0x8611).find("following error"), std::string::npos);
    EXPECT_NE(emcyText(0x8130).find("heartbeat"), std::string::npos);
    EXPECT_NE(emcyText(0x2310).find("over-current"), std::string::npos);
    // Unknown codes fall back to their class, marked as such.
    EXPECT_NE(emcyText(0x2345).find("current, device output side (class)"), std::string::npos);
    EXPECT_NE(emcyText(0x4999).find("temperature (class)"), std::string::npos);
    EXPECT_NE(emcyText(0xFF01).find("device specific"), std::string::npos);
    EXPECT_NE(emcyText(0x0000).find("no error"), std::string::npos);
    EXPECT_EQ(errorRegisterFor(0), 0);
    EXPECT_TRUE(errorRegisterFor(0x4310) & error_register::kTemperature);
}

TEST(Nmt, FramesAndHeartbeatStates) {
    const CanFrame f = encodeNmt(NmtCommand::Start, 0);
    EXPECT_EQ(f.id, 0u);
    EXPECT_EQ(f.len, 2);
    EXPECT_EQ(f.data[0], 0x01);
    NmtCommand c;
    int node = -1;
    ASSERT_TRUE(decodeNmt(encodeNmt(NmtCommand::ResetCommunication, 9), c, node));
    EXPECT_EQ(c, NmtCommand::ResetCommunication);
    EXPECT_EQ(node, 9);
    for (auto s :
         {NmtState::BootUp, NmtState::Stopped, NmtState::Operational, NmtState::PreOperational}) {
        NmtState back;
        ASSERT_TRUE(decodeHeartbeat(encodeHeartbeat(4, s), node, back));
        EXPECT_EQ(node, 4);
        EXPECT_EQ(back, s);
    }
    CanFrame bad = encodeHeartbeat(4, NmtState::Operational);
    bad.data[0] = 0x33;
    NmtState back;
    ASSERT_TRUE(decodeHeartbeat(bad, node, back));
    EXPECT_EQ(back, NmtState::Unknown);
}

TEST(Pdo, ProcessDataRoundTrip) {
    for (std::int32_t target : {0, 1, -1, 123456789, -2147483647 - 1, 2147483647}) {
        Rpdo1 r;
        ASSERT_TRUE(decodeRpdo1(encodeRpdo1(2, {0x000F, target}), r));
        EXPECT_EQ(r.controlword, 0x000F);
        EXPECT_EQ(r.target_counts, target);
        Tpdo1 t;
        ASSERT_TRUE(decodeTpdo1(encodeTpdo1(2, {0x0627, target, -1000}), t));
        EXPECT_EQ(t.torque_permille, -1000);
        EXPECT_EQ(t.statusword, 0x0627);
        EXPECT_EQ(t.actual_counts, target);
    }
    EXPECT_EQ(encodeRpdo1(2, {}).id, 0x202u);
    EXPECT_EQ(encodeRpdo2(2, 0).id, 0x302u);
    EXPECT_EQ(encodeTpdo1(2, {}).id, 0x182u);
    std::uint16_t cw = 0;
    ASSERT_TRUE(decodeRpdo2(encodeRpdo2(6, 0x0002), cw));
    EXPECT_EQ(cw, 0x0002);
    EXPECT_EQ(mapEntry(0x6040, 0, 16), 0x60400010u);
}

TEST(Pdo, StartupSequenceFollowsMappingProcedure) {
    const auto writes = cspStartupWrites(3, {});
    // For every PDO: invalidate COB-ID before touching its map, count written last, then validate.
    for (std::uint16_t comm :
         {std::uint16_t(0x1400), std::uint16_t(0x1401), std::uint16_t(0x1800)}) {
        const std::uint16_t map = static_cast<std::uint16_t>(comm + 0x200);
        int invalidated = -1, cleared = -1, counted = -1, validated = -1;
        for (size_t i = 0; i < writes.size(); ++i) {
            const SdoWrite& w = writes[i];
            if (w.address == SdoAddress{comm, 1}) {
                if (w.value & kCobIdInvalid)
                    invalidated = static_cast<int>(i);
                else
                    validated = static_cast<int>(i);
            }
            if (w.address == SdoAddress{map, 0})
                (w.value == 0 ? cleared : counted) = static_cast<int>(i);
        }
        EXPECT_LT(invalidated, cleared) << std::hex << comm;
        EXPECT_LT(cleared, counted) << std::hex << comm;
        EXPECT_LT(counted, validated) << std::hex << comm;
        EXPECT_GE(invalidated, 0);
    }
}

#include "devices/canopen/bus_state.h"

TEST(BusState, SocketCanErrorFramesDecode) {
    struct Row {
        std::uint32_t errorClass;
        std::uint8_t ctrl; // data[1]
        BusState state;
        const char* words;
    };
    // linux/can/error.h: CAN_ERR_BUSOFF 0x40, CAN_ERR_CRTL 0x04 with data[1] detail,
    // CAN_ERR_RESTARTED 0x100, CAN_ERR_ACK 0x20.
    const Row rows[] = {
        {0x040, 0x00, BusState::BusOff, "bus off"},
        {0x004, 0x20, BusState::ErrorPassive, "transmitter error passive"},
        {0x004, 0x10, BusState::ErrorPassive, "receiver error passive"},
        {0x004, 0x08, BusState::Warning, "warning level"},
        {0x004, 0x40, BusState::Good, "back to error active"},
        {0x100, 0x00, BusState::Good, "restarted"},
        {0x020, 0x00, BusState::Unknown, "no acknowledge"},
        {0x044, 0x20, BusState::BusOff, "bus off"}, // the worse state wins
    };
    for (const Row& r : rows) {
        const std::uint8_t data[8] = {0, r.ctrl, 0, 0, 0, 0, 0, 0};
        const ErrorFrameInfo info = decodeErrorFrame(r.errorClass, data, 8);
        EXPECT_EQ(info.state, r.state) << std::hex << r.errorClass << " " << int(r.ctrl);
        EXPECT_NE(info.text.find(r.words), std::string::npos) << info.text;
    }
    EXPECT_EQ(worse(BusState::Warning, BusState::BusOff), BusState::BusOff);
}
