#include "devices/canopen/pdo.h"

namespace cutcell::canopen {

namespace {
std::vector<SdoWrite> driveStartupWrites(int node, const DriveConfig& c, bool torque) {
    const auto n = static_cast<std::uint32_t>(node);
    std::vector<SdoWrite> w;
    auto add = [&w](std::uint16_t index, std::uint8_t sub, std::uint32_t value, int size) {
        w.push_back({{index, sub}, value, size});
    };
    auto pdo = [&](std::uint16_t comm, std::uint16_t map, std::uint32_t cobId, std::uint8_t type,
                   std::initializer_list<std::uint32_t> entries) {
        add(comm, 1, kCobIdInvalid | cobId, 4);
        add(map, 0, 0, 1);
        std::uint8_t sub = 1;
        for (std::uint32_t e : entries)
            add(map, sub++, e, 4);
        add(map, 0, static_cast<std::uint32_t>(entries.size()), 1);
        add(comm, 2, type, 1);
        add(comm, 1, cobId, 4);
    };
    add(od::kModesOfOperation, 0,
        static_cast<std::uint32_t>(torque ? kModeCyclicSyncTorque : kModeCyclicSyncPosition), 1);
    if (c.sync_counter_overflow > 0) add(od::kSyncCounterOverflow, 0, c.sync_counter_overflow, 1);
    add(od::kCommCyclePeriod, 0, c.cycle_period_us, 4);
    if (c.following_error_window_counts > 0)
        add(od::kFollowingErrorWindow, 0, c.following_error_window_counts, 4);
    pdo(od::kRpdoComm, od::kRpdoMap, cob::kRpdo1 + n, kTransmissionSync,
        {mapEntry(od::kControlword, 0, 16),
         torque ? mapEntry(od::kTargetTorque, 0, 16) : mapEntry(od::kTargetPosition, 0, 32)});
    pdo(static_cast<std::uint16_t>(od::kRpdoComm + 1), static_cast<std::uint16_t>(od::kRpdoMap + 1),
        cob::kRpdo2 + n, kTransmissionEvent, {mapEntry(od::kControlword, 0, 16)});
    pdo(od::kTpdoComm, od::kTpdoMap, cob::kTpdo1 + n, kTransmissionSync,
        {mapEntry(od::kStatusword, 0, 16), mapEntry(od::kPositionActual, 0, 32),
         mapEntry(od::kTorqueActual, 0, 16)});
    add(od::kProducerHeartbeat, 0, c.heartbeat_ms, 2);
    // The reaction first, then the consumer: it watches from the master's next heartbeat on.
    if (c.abort_connection_option >= 0)
        add(od::kAbortConnectionOption, 0, static_cast<std::uint32_t>(c.abort_connection_option),
            2);
    if (c.master_node > 0 && c.master_heartbeat_timeout_ms > 0)
        add(od::kConsumerHeartbeat, 1,
            (static_cast<std::uint32_t>(c.master_node) << 16) | c.master_heartbeat_timeout_ms, 4);
    return w;
}

} // namespace

std::vector<SdoWrite> cspStartupWrites(int node, const DriveConfig& c) {
    return driveStartupWrites(node, c, false);
}
std::vector<SdoWrite> cstStartupWrites(int node, const DriveConfig& c) {
    return driveStartupWrites(node, c, true);
}

std::vector<SdoWrite> encoderStartupWrites(int node, std::uint16_t heartbeat_ms,
                                           std::uint8_t sync_counter_overflow) {
    const std::uint32_t cobId = cob::kTpdo1 + static_cast<std::uint32_t>(node);
    std::vector<SdoWrite> w;
    // The encoder consumes the SYNC too: it must expect the counter's byte.
    if (sync_counter_overflow > 0)
        w.push_back({{od::kSyncCounterOverflow, 0}, sync_counter_overflow, 1});
    const std::vector<SdoWrite> rest = {
        {{od::kTpdoComm, 1}, kCobIdInvalid | cobId, 4},
        {{od::kTpdoMap, 0}, 0, 1},
        {{od::kTpdoMap, 1}, mapEntry(od::kEncoderPositionValue, 0, 32), 4},
        {{od::kTpdoMap, 0}, 1, 1},
        {{od::kTpdoComm, 2}, kTransmissionSync, 1},
        {{od::kTpdoComm, 1}, cobId, 4},
        {{od::kProducerHeartbeat, 0}, heartbeat_ms, 2}};
    w.insert(w.end(), rest.begin(), rest.end());
    return w;
}

CanFrame encodeRpdo1Torque(int node, std::uint16_t controlword, std::int16_t torque_permille) {
    CanFrame f;
    f.id = cob::kRpdo1 + static_cast<std::uint32_t>(node);
    f.len = kRpdo1TorqueBytes;
    putU16(f, 0, controlword);
    putU16(f, 2, static_cast<std::uint16_t>(torque_permille));
    return f;
}

CanFrame encodeEncoderTpdo(int node, std::int32_t counts) {
    CanFrame f;
    f.id = cob::kTpdo1 + static_cast<std::uint32_t>(node);
    f.len = kEncoderTpdoBytes;
    putU32(f, 0, static_cast<std::uint32_t>(counts));
    return f;
}

bool decodeEncoderTpdo(const CanFrame& f, std::int32_t& counts) {
    if (cob::functionOf(f.id) != cob::kTpdo1 || f.len != kEncoderTpdoBytes) return false;
    counts = static_cast<std::int32_t>(getU32(f, 0));
    return true;
}

CanFrame encodeRpdo1(int node, const Rpdo1& p) {
    CanFrame f;
    f.id = cob::kRpdo1 + static_cast<std::uint32_t>(node);
    f.len = kRpdo1Bytes;
    putU16(f, 0, p.controlword);
    putU32(f, 2, static_cast<std::uint32_t>(p.target_counts));
    return f;
}

CanFrame encodeRpdo2(int node, std::uint16_t controlword) {
    CanFrame f;
    f.id = cob::kRpdo2 + static_cast<std::uint32_t>(node);
    f.len = kRpdo2Bytes;
    putU16(f, 0, controlword);
    return f;
}

CanFrame encodeTpdo1(int node, const Tpdo1& p) {
    CanFrame f;
    f.id = cob::kTpdo1 + static_cast<std::uint32_t>(node);
    f.len = kTpdo1Bytes;
    putU16(f, 0, p.statusword);
    putU32(f, 2, static_cast<std::uint32_t>(p.actual_counts));
    putU16(f, 6, static_cast<std::uint16_t>(p.torque_permille));
    return f;
}

bool decodeRpdo1(const CanFrame& f, Rpdo1& out) {
    if (cob::functionOf(f.id) != cob::kRpdo1 || f.len != kRpdo1Bytes) return false;
    out.controlword = getU16(f, 0);
    out.target_counts = static_cast<std::int32_t>(getU32(f, 2));
    return true;
}

bool decodeRpdo2(const CanFrame& f, std::uint16_t& controlword) {
    if (cob::functionOf(f.id) != cob::kRpdo2 || f.len != kRpdo2Bytes) return false;
    controlword = getU16(f, 0);
    return true;
}

bool decodeTpdo1(const CanFrame& f, Tpdo1& out) {
    if (cob::functionOf(f.id) != cob::kTpdo1 || f.len != kTpdo1Bytes) return false;
    out.statusword = getU16(f, 0);
    out.actual_counts = static_cast<std::int32_t>(getU32(f, 2));
    out.torque_permille = static_cast<std::int16_t>(getU16(f, 6));
    return true;
}

} // namespace cutcell::canopen
