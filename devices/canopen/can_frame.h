#pragma once
// A classic CAN data frame as plain bytes: the protocol layer (CANopen codec, CiA 402 state
// machines, the simulated node) works on this type and never sees Qt, so it can be tested as
// tables of frames in and frames out. The Qt transport converts at the edge (qt_can_frame.h).
#include <array>
#include <cstddef>
#include <cstdint>

namespace cutcell::canopen {

struct CanFrame {
    std::uint32_t id = 0; // 11-bit COB-ID
    std::uint8_t len = 0; // 0..8
    std::array<std::uint8_t, 8> data{};

    bool operator==(const CanFrame&) const = default;
};

inline std::uint16_t getU16(const CanFrame& f, int at) {
    return static_cast<std::uint16_t>(f.data[static_cast<std::size_t>(at)] |
                                      (f.data[static_cast<std::size_t>(at + 1)] << 8));
}
inline std::uint32_t getU32(const CanFrame& f, int at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i)
        v = (v << 8) | f.data[static_cast<std::size_t>(at + i)];
    return v;
}
inline void putU16(CanFrame& f, int at, std::uint16_t v) {
    f.data[static_cast<std::size_t>(at)] = static_cast<std::uint8_t>(v & 0xFF);
    f.data[static_cast<std::size_t>(at + 1)] = static_cast<std::uint8_t>(v >> 8);
}
inline void putU32(CanFrame& f, int at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        f.data[static_cast<std::size_t>(at + i)] = static_cast<std::uint8_t>((v >> (8 * i)) & 0xFF);
}

// CANopen predefined connection set (CiA 301): function code + node id.
namespace cob {
inline constexpr std::uint32_t kNmt = 0x000;
inline constexpr std::uint32_t kSync = 0x080;
inline constexpr std::uint32_t kEmcy = 0x080;      // + node id (1..127)
inline constexpr std::uint32_t kTpdo1 = 0x180;     // + node id
inline constexpr std::uint32_t kRpdo1 = 0x200;     // + node id
inline constexpr std::uint32_t kRpdo2 = 0x300;     // + node id
inline constexpr std::uint32_t kSdoTx = 0x580;     // server -> client, + node id
inline constexpr std::uint32_t kSdoRx = 0x600;     // client -> server, + node id
inline constexpr std::uint32_t kHeartbeat = 0x700; // + node id
inline constexpr std::uint32_t functionOf(std::uint32_t id) {
    return id & 0x780;
}
inline constexpr int nodeOf(std::uint32_t id) {
    return static_cast<int>(id & 0x7F);
}
} // namespace cob

} // namespace cutcell::canopen
