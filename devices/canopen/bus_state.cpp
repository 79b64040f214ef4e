#include "devices/canopen/bus_state.h"

namespace cutcell::canopen {
namespace {
// linux/can/error.h
constexpr std::uint32_t kErrTxTimeout = 0x001;
constexpr std::uint32_t kErrCtrl = 0x004;
constexpr std::uint32_t kErrProt = 0x008;
constexpr std::uint32_t kErrAck = 0x020;
constexpr std::uint32_t kErrBusOff = 0x040;
constexpr std::uint32_t kErrBusError = 0x080;
constexpr std::uint32_t kErrRestarted = 0x100;
constexpr std::uint8_t kCtrlRxOverflow = 0x01;
constexpr std::uint8_t kCtrlTxOverflow = 0x02;
constexpr std::uint8_t kCtrlRxWarning = 0x04;
constexpr std::uint8_t kCtrlTxWarning = 0x08;
constexpr std::uint8_t kCtrlRxPassive = 0x10;
constexpr std::uint8_t kCtrlTxPassive = 0x20;
constexpr std::uint8_t kCtrlActive = 0x40;

void append(std::string& s, const char* what) {
    if (!s.empty()) s += ", ";
    s += what;
}
} // namespace

const char* toString(BusState s) {
    switch (s) {
    case BusState::Unknown:
        return "unknown";
    case BusState::Good:
        return "error active";
    case BusState::Warning:
        return "error warning";
    case BusState::ErrorPassive:
        return "error passive";
    case BusState::BusOff:
        return "bus off";
    case BusState::Disconnected:
        return "disconnected";
    }
    return "unknown";
}

BusState worse(BusState a, BusState b) {
    return static_cast<int>(a) >= static_cast<int>(b) ? a : b;
}

ErrorFrameInfo decodeErrorFrame(std::uint32_t c, const std::uint8_t* d, int len) {
    ErrorFrameInfo r;
    const std::uint8_t ctrl = len > 1 ? d[1] : 0;
    if (c & kErrBusOff) {
        r.state = BusState::BusOff;
        append(r.text, "bus off");
    }
    if (c & kErrCtrl) {
        if (ctrl & (kCtrlRxPassive | kCtrlTxPassive)) {
            r.state = worse(r.state, BusState::ErrorPassive);
            append(r.text,
                   ctrl & kCtrlTxPassive ? "transmitter error passive" : "receiver error passive");
        } else if (ctrl & (kCtrlRxWarning | kCtrlTxWarning)) {
            r.state = worse(r.state, BusState::Warning);
            append(r.text, "error counter reached warning level");
        }
        if (ctrl & kCtrlActive) {
            if (r.state == BusState::Unknown) r.state = BusState::Good;
            append(r.text, "back to error active");
        }
        if (ctrl & (kCtrlRxOverflow | kCtrlTxOverflow))
            append(r.text, "controller buffer overflow");
    }
    if (c & kErrRestarted) {
        r.restarted = true;
        if (r.state == BusState::Unknown) r.state = BusState::Good;
        append(r.text, "controller restarted");
    }
    if (c & kErrTxTimeout) append(r.text, "transmit timeout");
    if (c & kErrAck) append(r.text, "no acknowledge (no other node on the bus?)");
    if (c & kErrProt) append(r.text, "protocol violation");
    if (c & kErrBusError) append(r.text, "bus error");
    if (r.text.empty()) r.text = "error frame";
    return r;
}

} // namespace cutcell::canopen
