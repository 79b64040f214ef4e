#pragma once
// CiA 402 drive profile: the power state machine seen from both ends.
//  - Master side: decode a statusword into a state; pick the controlword that walks a drive
//    one step toward a goal (Operation Enabled, Disabled, Quick Stop, fault reset).
//  - Slave side (the drive simulator): apply a controlword to the state machine.
// Pure functions, no I/O.
#include <cstdint>

namespace cutcell::canopen {

enum class Cia402State : std::uint8_t {
    NotReadyToSwitchOn,
    SwitchOnDisabled,
    ReadyToSwitchOn,
    SwitchedOn,
    OperationEnabled,
    QuickStopActive,
    FaultReactionActive,
    Fault,
    Unknown,
};
const char* toString(Cia402State s);

// Controlword commands (CiA 402, bits 0..3 and 7).
namespace cw {
inline constexpr std::uint16_t kShutdown = 0x0006;
inline constexpr std::uint16_t kSwitchOn = 0x0007;
inline constexpr std::uint16_t kDisableOperation = 0x0007;
inline constexpr std::uint16_t kEnableOperation = 0x000F;
inline constexpr std::uint16_t kDisableVoltage = 0x0000;
inline constexpr std::uint16_t kQuickStop = 0x0002;
inline constexpr std::uint16_t kFaultResetBit = 0x0080;
} // namespace cw

// Statusword bits used beyond the state.
namespace sw {
inline constexpr std::uint16_t kVoltageEnabled = 0x0010;
inline constexpr std::uint16_t kWarning = 0x0080;
inline constexpr std::uint16_t kRemote = 0x0200;
inline constexpr std::uint16_t kTargetReached = 0x0400;
inline constexpr std::uint16_t kFollowingError = 0x2000; // CSP: bit 13
} // namespace sw

Cia402State decodeStatusword(std::uint16_t statusword);
// The state bits of a statusword (bits 0..3, 5, 6); other bits are OR-ed in by the caller.
std::uint16_t encodeStatusword(Cia402State s);

// What the master wants of a drive.
enum class DriveGoal : std::uint8_t { Disabled, OperationEnabled, QuickStop };

// Controlword that moves a drive in state s one step toward goal. A drive in Fault gets the
// goal's command without the reset bit: a fault reset is a separate, explicit edge.
std::uint16_t controlwordToward(Cia402State s, DriveGoal goal);

// Slave side: the state after receiving controlword cw in state s. The fault reset acts on the
// rising edge of bit 7 only (previous controlword prev). Unknown commands leave the state.
Cia402State applyControlword(Cia402State s, std::uint16_t prev, std::uint16_t cw);

// Whether the power stage is on (torque) in state s.
bool torqueOn(Cia402State s);

// Modes of operation (0x6060/0x6061).
inline constexpr std::int8_t kModeCyclicSyncPosition = 8;
inline constexpr std::int8_t kModeCyclicSyncTorque = 10;

} // namespace cutcell::canopen
