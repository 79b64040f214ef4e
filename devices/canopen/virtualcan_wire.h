#pragma once
// The line protocol of Qt's virtualcan bus, checked before a line is relayed.
//
// A client writes one line per frame, "<channel>:<id>#<flags>#<hex data>" (e.g.
// "can0:384#L#2f0060000800" - id in decimal, flags from R X F B E L), or a command,
// "connect:can0" / "disconnect:can0". The bus server relays "<id>#<flags>#<hex data>" to every
// other client on that channel. Qt's client parses what it is given without checks: a line
// without two '#' (e.g. "can0:hello" relayed as "hello") crashes every client on the bus
// (Qt 6.4, an out-of-range list index). CutCell's relay (virtualcan_host.cpp) passes on only
// lines this parser accepts.
#include <string>
#include <string_view>

namespace cutcell::canopen {

enum class VirtualCanLineKind { Frame, Connect, Disconnect, Malformed };

struct VirtualCanLine {
    VirtualCanLineKind kind = VirtualCanLineKind::Malformed;
    int channel = -1;      // 0 or 1 (Qt offers can0 and can1)
    std::string_view body; // Frame: what is relayed ("<id>#<flags>#<hex>")
    std::string why;       // Malformed: what is wrong, for the log
};

inline constexpr int kVirtualCanChannels = 2;
inline constexpr size_t kVirtualCanMaxLine = 200; // a CAN FD frame of 64 bytes is ~150

// `line` without its line feed (surrounding white space is ignored, as Qt does).
VirtualCanLine parseVirtualCanLine(std::string_view line);

} // namespace cutcell::canopen
