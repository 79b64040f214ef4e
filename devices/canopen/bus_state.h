#pragma once
// CAN controller error states (ISO 11898-1 fault confinement) and their decoding from Linux
// SocketCAN error frames (linux/can/error.h layout: class bits in the identifier, controller
// detail in data[1]). Qt hands these frames over as QCanBusFrame::ErrorFrame.
#include <cstdint>
#include <string>

namespace cutcell::canopen {

enum class BusState : std::uint8_t { Unknown, Good, Warning, ErrorPassive, BusOff, Disconnected };
const char* toString(BusState s);

struct ErrorFrameInfo {
    BusState state = BusState::Unknown; // Unknown: the frame says nothing about the state
    bool restarted = false;             // controller restarted after bus-off
    std::string text;                   // what the frame reports, for the log
};

// id: the error class bits (CAN_ERR_* of the 29-bit identifier), data: the 8 bytes.
ErrorFrameInfo decodeErrorFrame(std::uint32_t errorClass, const std::uint8_t* data, int len);

// Worse of two states (for aggregating reports).
BusState worse(BusState a, BusState b);

} // namespace cutcell::canopen
