#pragma once
// CANopen emergency messages (EMCY, 0x80 + node): error code (CiA 301 classes, CiA 402 drive
// codes), error register, 5 manufacturer bytes.
#include "devices/canopen/can_frame.h"

#include <cstdint>
#include <string>

namespace cutcell::canopen {

struct Emcy {
    int node = 0;
    std::uint16_t error_code = 0; // 0x0000 = error reset / no error
    std::uint8_t error_register = 0;
};

CanFrame encodeEmcy(int node, std::uint16_t errorCode, std::uint8_t errorRegister);
// False when the frame is not an 8-byte EMCY of a node (ids 0x81..0xFF).
bool decodeEmcy(const CanFrame& f, Emcy& out);

// "0x8611 following error" - the exact code when known (CiA 402 drive codes, CiA 301
// communication codes), otherwise its class ("0x2345 current, device output side (class)").
std::string emcyText(std::uint16_t errorCode);

namespace emcy_code {
inline constexpr std::uint16_t kNone = 0x0000;
inline constexpr std::uint16_t kGeneric = 0x1000;
inline constexpr std::uint16_t kOverCurrent = 0x2310;
inline constexpr std::uint16_t kDcLinkOverVoltage = 0x3210;
inline constexpr std::uint16_t kDriveOverTemperature = 0x4310;
inline constexpr std::uint16_t kHeartbeat = 0x8130; // life guard / heartbeat error
inline constexpr std::uint16_t kBusOffRecovered = 0x8140;
inline constexpr std::uint16_t kCommunication = 0x8100;  // generic: a SYNC counter skipped
inline constexpr std::uint16_t kSyncDataLength = 0x8240; // a SYNC without (or with) a counter
inline constexpr std::uint16_t kFollowingError = 0x8611;
} // namespace emcy_code

// Error register bits (0x1001).
namespace error_register {
inline constexpr std::uint8_t kGeneric = 0x01;
inline constexpr std::uint8_t kCurrent = 0x02;
inline constexpr std::uint8_t kVoltage = 0x04;
inline constexpr std::uint8_t kTemperature = 0x08;
inline constexpr std::uint8_t kCommunication = 0x10;
inline constexpr std::uint8_t kProfile = 0x20;
} // namespace error_register

// The error register bits a given error code sets (generic bit always set for a real error).
std::uint8_t errorRegisterFor(std::uint16_t errorCode);

} // namespace cutcell::canopen
