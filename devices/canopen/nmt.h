#pragma once
// CANopen network management: NMT commands (0x000), node states as reported by heartbeat
// and boot-up messages (0x700 + node), SYNC (0x080).
#include "devices/canopen/can_frame.h"

#include <cstdint>

namespace cutcell::canopen {

enum class NmtCommand : std::uint8_t {
    Start = 0x01,
    Stop = 0x02,
    EnterPreOperational = 0x80,
    ResetNode = 0x81,
    ResetCommunication = 0x82,
};
const char* toString(NmtCommand c);

// Heartbeat state byte (CiA 301).
enum class NmtState : std::uint8_t {
    BootUp = 0x00,
    Stopped = 0x04,
    Operational = 0x05,
    PreOperational = 0x7F,
    Unknown = 0xFF, // not heard yet, or an invalid byte
};
const char* toString(NmtState s);

// node 0 addresses every node.
CanFrame encodeNmt(NmtCommand c, int node);
bool decodeNmt(const CanFrame& f, NmtCommand& command, int& node);

CanFrame encodeHeartbeat(int node, NmtState s);
// False when f is not a heartbeat/boot-up frame; invalid state bytes decode to Unknown.
bool decodeHeartbeat(const CanFrame& f, int& node, NmtState& s);

// A SYNC; with a counter (1..overflow, CiA 301 0x1019) it carries one byte.
CanFrame encodeSync(std::uint8_t counter = 0);
// A SYNC frame (id 0x080, 0 or 1 byte): its counter, 0 when it has none.
bool decodeSync(const CanFrame& f, std::uint8_t& counter);
// The counter after `last` (1 after overflow; 1 when there was none yet).
std::uint8_t nextSyncCounter(std::uint8_t last, std::uint8_t overflow);

} // namespace cutcell::canopen
