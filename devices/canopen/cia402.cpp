#include "devices/canopen/cia402.h"

namespace cutcell::canopen {

const char* toString(Cia402State s) {
    switch (s) {
    case Cia402State::NotReadyToSwitchOn:
        return "Not ready to switch on";
    case Cia402State::SwitchOnDisabled:
        return "Switch on disabled";
    case Cia402State::ReadyToSwitchOn:
        return "Ready to switch on";
    case Cia402State::SwitchedOn:
        return "Switched on";
    case Cia402State::OperationEnabled:
        return "Operation enabled";
    case Cia402State::QuickStopActive:
        return "Quick stop active";
    case Cia402State::FaultReactionActive:
        return "Fault reaction active";
    case Cia402State::Fault:
        return "Fault";
    case Cia402State::Unknown:
        return "Unknown";
    }
    return "Unknown";
}

Cia402State decodeStatusword(std::uint16_t s) {
    // CiA 402 table: bits 6,5,3,2,1,0 (mask 0x6F), or 6,3,2,1,0 (0x4F) where bit 5 is free.
    switch (s & 0x4F) {
    case 0x00:
        return Cia402State::NotReadyToSwitchOn;
    case 0x40:
        return Cia402State::SwitchOnDisabled;
    case 0x0F:
        return Cia402State::FaultReactionActive;
    case 0x08:
        return Cia402State::Fault;
    default:
        break;
    }
    switch (s & 0x6F) {
    case 0x21:
        return Cia402State::ReadyToSwitchOn;
    case 0x23:
        return Cia402State::SwitchedOn;
    case 0x27:
        return Cia402State::OperationEnabled;
    case 0x07:
        return Cia402State::QuickStopActive;
    default:
        return Cia402State::Unknown;
    }
}

std::uint16_t encodeStatusword(Cia402State s) {
    switch (s) {
    case Cia402State::NotReadyToSwitchOn:
        return 0x0000;
    case Cia402State::SwitchOnDisabled:
        return 0x0040;
    case Cia402State::ReadyToSwitchOn:
        return 0x0021;
    case Cia402State::SwitchedOn:
        return 0x0023;
    case Cia402State::OperationEnabled:
        return 0x0027;
    case Cia402State::QuickStopActive:
        return 0x0007;
    case Cia402State::FaultReactionActive:
        return 0x000F;
    case Cia402State::Fault:
        return 0x0008;
    case Cia402State::Unknown:
        return 0x0000;
    }
    return 0;
}

std::uint16_t controlwordToward(Cia402State s, DriveGoal goal) {
    switch (goal) {
    case DriveGoal::Disabled:
        // Disable voltage: the power stage opens at once from every state (stop category 0).
        return cw::kDisableVoltage;
    case DriveGoal::QuickStop:
        if (s == Cia402State::OperationEnabled || s == Cia402State::QuickStopActive)
            return cw::kQuickStop;
        return cw::kDisableVoltage; // not moving under power: nothing to decelerate
    case DriveGoal::OperationEnabled:
        switch (s) {
        case Cia402State::SwitchOnDisabled:
            return cw::kShutdown;
        case Cia402State::ReadyToSwitchOn:
            return cw::kSwitchOn;
        case Cia402State::SwitchedOn:
        case Cia402State::OperationEnabled:
            return cw::kEnableOperation;
        case Cia402State::QuickStopActive:
            return cw::kQuickStop; // finish the stop first
        default:
            return cw::kDisableVoltage;
        }
    }
    return cw::kDisableVoltage;
}

namespace {

// Command decoding of CiA 402 (bits 7,3,2,1,0).
bool isShutdown(std::uint16_t c) {
    return (c & 0x87) == 0x06;
}
bool isSwitchOn(std::uint16_t c) {
    return (c & 0x8F) == 0x07;
}
bool isEnableOperation(std::uint16_t c) {
    return (c & 0x8F) == 0x0F;
}
bool isDisableVoltage(std::uint16_t c) {
    return (c & 0x82) == 0x00;
}
bool isQuickStop(std::uint16_t c) {
    return (c & 0x86) == 0x02;
}

} // namespace

Cia402State applyControlword(Cia402State s, std::uint16_t prev, std::uint16_t c) {
    using S = Cia402State;
    if (s == S::Fault) {
        const bool rising = (c & cw::kFaultResetBit) && !(prev & cw::kFaultResetBit);
        return rising ? S::SwitchOnDisabled : S::Fault; // transition 15
    }
    if (s == S::FaultReactionActive || s == S::NotReadyToSwitchOn || s == S::Unknown) return s;
    if (c & cw::kFaultResetBit) return s; // reset bit outside Fault: no command
    switch (s) {
    case S::SwitchOnDisabled:
        return isShutdown(c) ? S::ReadyToSwitchOn : s; // 2
    case S::ReadyToSwitchOn:
        if (isSwitchOn(c)) return S::SwitchedOn;                               // 3
        if (isEnableOperation(c)) return S::OperationEnabled;                  // 3 + 4 (allowed)
        if (isDisableVoltage(c) || isQuickStop(c)) return S::SwitchOnDisabled; // 7
        return s;
    case S::SwitchedOn:
        if (isEnableOperation(c)) return S::OperationEnabled;                  // 4
        if (isShutdown(c)) return S::ReadyToSwitchOn;                          // 6
        if (isDisableVoltage(c) || isQuickStop(c)) return S::SwitchOnDisabled; // 10
        return s;
    case S::OperationEnabled:
        if (isSwitchOn(c)) return S::SwitchedOn;             // 5 (disable operation)
        if (isShutdown(c)) return S::ReadyToSwitchOn;        // 8
        if (isDisableVoltage(c)) return S::SwitchOnDisabled; // 9
        if (isQuickStop(c)) return S::QuickStopActive;       // 11
        return s;
    case S::QuickStopActive:
        // 12; transition 16 (back to enabled) needs quick stop option 5..8, which this profile
        // subset does not offer: the drive stops, then drops to Switch on disabled by itself.
        return isDisableVoltage(c) ? S::SwitchOnDisabled : s;
    default:
        return s;
    }
}

bool torqueOn(Cia402State s) {
    return s == Cia402State::OperationEnabled || s == Cia402State::QuickStopActive ||
           s == Cia402State::FaultReactionActive;
}

} // namespace cutcell::canopen
