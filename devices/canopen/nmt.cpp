#include "devices/canopen/nmt.h"

namespace cutcell::canopen {

const char* toString(NmtCommand c) {
    switch (c) {
    case NmtCommand::Start:
        return "start";
    case NmtCommand::Stop:
        return "stop";
    case NmtCommand::EnterPreOperational:
        return "enter pre-operational";
    case NmtCommand::ResetNode:
        return "reset node";
    case NmtCommand::ResetCommunication:
        return "reset communication";
    }
    return "unknown";
}

const char* toString(NmtState s) {
    switch (s) {
    case NmtState::BootUp:
        return "Boot-up";
    case NmtState::Stopped:
        return "Stopped";
    case NmtState::Operational:
        return "Operational";
    case NmtState::PreOperational:
        return "Pre-operational";
    case NmtState::Unknown:
        return "Unknown";
    }
    return "Unknown";
}

CanFrame encodeNmt(NmtCommand c, int node) {
    CanFrame f;
    f.id = cob::kNmt;
    f.len = 2;
    f.data[0] = static_cast<std::uint8_t>(c);
    f.data[1] = static_cast<std::uint8_t>(node);
    return f;
}

bool decodeNmt(const CanFrame& f, NmtCommand& command, int& node) {
    if (f.id != cob::kNmt || f.len != 2) return false;
    switch (f.data[0]) {
    case 0x01:
    case 0x02:
    case 0x80:
    case 0x81:
    case 0x82:
        command = static_cast<NmtCommand>(f.data[0]);
        break;
    default:
        return false;
    }
    node = f.data[1];
    return true;
}

CanFrame encodeHeartbeat(int node, NmtState s) {
    CanFrame f;
    f.id = cob::kHeartbeat + static_cast<std::uint32_t>(node);
    f.len = 1;
    f.data[0] = static_cast<std::uint8_t>(s);
    return f;
}

bool decodeHeartbeat(const CanFrame& f, int& node, NmtState& s) {
    if (cob::functionOf(f.id) != cob::kHeartbeat || cob::nodeOf(f.id) == 0 || f.len != 1)
        return false;
    node = cob::nodeOf(f.id);
    switch (f.data[0] & 0x7F) { // bit 7 is the toggle bit of node guarding
    case 0x00:
        s = NmtState::BootUp;
        break;
    case 0x04:
        s = NmtState::Stopped;
        break;
    case 0x05:
        s = NmtState::Operational;
        break;
    case 0x7F:
        s = NmtState::PreOperational;
        break;
    default:
        s = NmtState::Unknown;
        break;
    }
    return true;
}

CanFrame encodeSync(std::uint8_t counter) {
    CanFrame f;
    f.id = cob::kSync;
    f.len = counter > 0 ? 1 : 0;
    f.data[0] = counter;
    return f;
}

bool decodeSync(const CanFrame& f, std::uint8_t& counter) {
    if (f.id != cob::kSync || f.len > 1) return false;
    counter = f.len == 1 ? f.data[0] : 0;
    return true;
}

std::uint8_t nextSyncCounter(std::uint8_t last, std::uint8_t overflow) {
    return last == 0 || last >= overflow ? 1 : static_cast<std::uint8_t>(last + 1);
}

} // namespace cutcell::canopen
