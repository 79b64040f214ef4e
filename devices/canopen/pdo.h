#pragma once
// The process data of a CSP drive and how the master maps it (CiA 301 PDO mapping, CiA 402
// objects):
//   RPDO1 (0x200 + node, synchronous): controlword 0x6040 + target position 0x607A
//   RPDO2 (0x300 + node, asynchronous): controlword 0x6040 alone - the emergency-stop channel,
//         acted on at once instead of at the next SYNC
//   TPDO1 (0x180 + node, synchronous): statusword 0x6041 + position actual value 0x6064 +
//         torque actual value 0x6077 (per mille of the rated torque 0x6076)
// A drive in cyclic synchronous torque mode (CST, 0x6060 = 10) has RPDO1 = controlword +
// target torque 0x6071 (per mille of 0x6076); the rest is the same.
// A CiA 406 encoder (device type profile 406) has one TPDO1 (0x180 + node, synchronous):
// position value 0x6004 (32 bit, counts).
#include "devices/canopen/can_frame.h"
#include "devices/canopen/cia402.h"
#include "devices/canopen/sdo.h"

#include <cstdint>
#include <vector>

namespace cutcell::canopen {

namespace od {
inline constexpr std::uint16_t kDeviceType = 0x1000;
inline constexpr std::uint16_t kErrorRegister = 0x1001;
inline constexpr std::uint16_t kCommCyclePeriod = 0x1006;     // us
inline constexpr std::uint16_t kSyncCounterOverflow = 0x1019; // 0: SYNC without counter
inline constexpr std::uint16_t kConsumerHeartbeat = 0x1016;   // sub 1: node << 16 | ms
inline constexpr std::uint16_t kProducerHeartbeat = 0x1017;   // ms
inline constexpr std::uint16_t kIdentity = 0x1018;
inline constexpr std::uint16_t kRpdoComm = 0x1400;              // + n
inline constexpr std::uint16_t kRpdoMap = 0x1600;               // + n
inline constexpr std::uint16_t kTpdoComm = 0x1800;              // + n
inline constexpr std::uint16_t kTpdoMap = 0x1A00;               // + n
inline constexpr std::uint16_t kAbortConnectionOption = 0x6007; // reaction to a lost master
inline constexpr std::uint16_t kErrorCode = 0x603F;
inline constexpr std::uint16_t kControlword = 0x6040;
inline constexpr std::uint16_t kStatusword = 0x6041;
inline constexpr std::uint16_t kQuickStopOption = 0x605A;
inline constexpr std::uint16_t kModesOfOperation = 0x6060;
inline constexpr std::uint16_t kModesDisplay = 0x6061;
inline constexpr std::uint16_t kPositionActual = 0x6064;
inline constexpr std::uint16_t kFollowingErrorWindow = 0x6065; // counts
inline constexpr std::uint16_t kTargetPosition = 0x607A;
inline constexpr std::uint16_t kTargetTorque = 0x6071;         // per mille of 0x6076
inline constexpr std::uint16_t kMotorRatedTorque = 0x6076;     // mN m
inline constexpr std::uint16_t kTorqueActual = 0x6077;         // per mille of 0x6076
inline constexpr std::uint16_t kQuickStopDecel = 0x6085;       // counts/s^2
inline constexpr std::uint32_t kDeviceTypeCia402 = 0x00020192; // profile 402, servo drive
// CiA 406 encoder: position value (counts) and the device type (profile 406, multi-turn
// absolute rotary encoder in the additional information).
inline constexpr std::uint16_t kEncoderPositionValue = 0x6004;
inline constexpr std::uint32_t kDeviceTypeCia406 = 0x00020196;
} // namespace od

// A mapping entry: index << 16 | sub << 8 | bit length.
constexpr std::uint32_t mapEntry(std::uint16_t index, std::uint8_t sub, std::uint8_t bits) {
    return (static_cast<std::uint32_t>(index) << 16) | (static_cast<std::uint32_t>(sub) << 8) |
           bits;
}
inline constexpr std::uint32_t kCobIdInvalid = 0x80000000u; // bit 31: PDO does not exist
inline constexpr std::uint8_t kTransmissionSync = 1;        // every SYNC
inline constexpr std::uint8_t kTransmissionEvent = 255;     // event-driven (asynchronous)

// One expedited SDO write of the start-up configuration.
struct SdoWrite {
    SdoAddress address;
    std::uint32_t value = 0;
    int size = 0;
};

struct DriveConfig {
    std::uint32_t cycle_period_us = 4000;
    std::uint16_t heartbeat_ms = 100;
    std::uint32_t following_error_window_counts = 0; // 0: leave the drive's own
    // The drive watches the master: it consumes the master's heartbeat (0x1016:01 = master
    // node << 16 | timeout ms) and reacts to its loss by 0x6007. 0 / -1: not written.
    int master_node = 0;
    std::uint16_t master_heartbeat_timeout_ms = 0;
    int abort_connection_option = -1;
    // CiA 301 0x1019: the SYNC carries a counter 1..overflow (0: no counter). The drive checks
    // that it advances by one: a skipped or repeated SYNC (a second producer, lost frames) is
    // a communication error, answered by 0x6007 like a lost master. Written before 0x1006.
    std::uint8_t sync_counter_overflow = 0;
};

// 0x6007 abort connection option codes (CiA 402).
namespace abort_connection {
inline constexpr int kNoAction = 0;
inline constexpr int kFault = 1;
inline constexpr int kDisableVoltage = 2;
inline constexpr int kQuickStop = 3;
} // namespace abort_connection

// The SDO writes that put a drive into CSP with the PDOs above (CiA 301 mapping procedure:
// invalidate the PDO, clear the map, write entries, set the count, set the type, validate).
std::vector<SdoWrite> cspStartupWrites(int node, const DriveConfig& c);
// The same for a drive in CST: 0x6060 = 10, RPDO1 = controlword + target torque 0x6071.
std::vector<SdoWrite> cstStartupWrites(int node, const DriveConfig& c);
// A CiA 406 encoder: TPDO1 = position value 0x6004 on every SYNC, its heartbeat.
std::vector<SdoWrite> encoderStartupWrites(int node, std::uint16_t heartbeat_ms,
                                           std::uint8_t sync_counter_overflow = 0);

struct Rpdo1 {
    std::uint16_t controlword = 0;
    std::int32_t target_counts = 0;
};
struct Tpdo1 {
    std::uint16_t statusword = 0;
    std::int32_t actual_counts = 0;
    std::int16_t torque_permille = 0;
};
inline constexpr int kRpdo1Bytes = 6;
inline constexpr int kRpdo1TorqueBytes = 4; // CST: controlword + target torque
inline constexpr int kEncoderTpdoBytes = 4; // CiA 406: position value
inline constexpr int kRpdo2Bytes = 2;
inline constexpr int kTpdo1Bytes = 8;

CanFrame encodeRpdo1(int node, const Rpdo1& p);
CanFrame encodeRpdo1Torque(int node, std::uint16_t controlword, std::int16_t torque_permille);
CanFrame encodeEncoderTpdo(int node, std::int32_t counts);
bool decodeEncoderTpdo(const CanFrame& f, std::int32_t& counts);
CanFrame encodeRpdo2(int node, std::uint16_t controlword);
CanFrame encodeTpdo1(int node, const Tpdo1& p);
bool decodeRpdo1(const CanFrame& f, Rpdo1& out);
bool decodeRpdo2(const CanFrame& f, std::uint16_t& controlword);
bool decodeTpdo1(const CanFrame& f, Tpdo1& out);

} // namespace cutcell::canopen
