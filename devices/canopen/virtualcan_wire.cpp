#include "devices/canopen/virtualcan_wire.h"

#include <cstdint>

namespace cutcell::canopen {
namespace {

std::string_view trimmed(std::string_view s) {
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!s.empty() && space(s.front()))
        s.remove_prefix(1);
    while (!s.empty() && space(s.back()))
        s.remove_suffix(1);
    return s;
}

// "can0" / "can1"
int channelOf(std::string_view s) {
    if (s.size() != 4 || s.substr(0, 3) != "can") return -1;
    const int c = s[3] - '0';
    return c >= 0 && c < kVirtualCanChannels ? c : -1;
}

bool isHex(char c) {
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

VirtualCanLine malformed(std::string why) {
    VirtualCanLine l;
    l.why = std::move(why);
    return l;
}

} // namespace

VirtualCanLine parseVirtualCanLine(std::string_view raw) {
    if (raw.size() > kVirtualCanMaxLine)
        return malformed("longer than " + std::to_string(kVirtualCanMaxLine) + " characters");
    const std::string_view line = trimmed(raw);
    for (const char c : line)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7E)
            return malformed("not printable ASCII");
    const size_t colon = line.find(':');
    if (colon == std::string_view::npos) return malformed("no ':' after the channel");
    const std::string_view head = line.substr(0, colon);
    const std::string_view rest = line.substr(colon + 1);
    if (head == "connect" || head == "disconnect") {
        VirtualCanLine l;
        l.channel = channelOf(rest);
        if (l.channel < 0) return malformed("unknown channel in " + std::string(head));
        l.kind = head == "connect" ? VirtualCanLineKind::Connect : VirtualCanLineKind::Disconnect;
        return l;
    }
    VirtualCanLine l;
    l.channel = channelOf(head);
    if (l.channel < 0) return malformed("unknown channel (can0 or can1)");
    const size_t hash1 = rest.find('#');
    const size_t hash2 = hash1 == std::string_view::npos ? hash1 : rest.find('#', hash1 + 1);
    if (hash2 == std::string_view::npos || rest.find('#', hash2 + 1) != std::string_view::npos)
        return malformed("not <id>#<flags>#<data>");
    const std::string_view id = rest.substr(0, hash1);
    const std::string_view flags = rest.substr(hash1 + 1, hash2 - hash1 - 1);
    const std::string_view data = rest.substr(hash2 + 1);
    if (id.empty() || id.size() > 9) return malformed("frame id not 1 to 9 decimal digits");
    std::uint32_t value = 0;
    for (const char c : id) {
        if (c < '0' || c > '9') return malformed("frame id not decimal");
        value = value * 10 + static_cast<std::uint32_t>(c - '0');
    }
    bool extended = false, fd = false;
    std::string seen;
    for (const char c : flags) {
        if (std::string_view("RXFBEL").find(c) == std::string_view::npos)
            return malformed(std::string("unknown flag '") + c + "'");
        if (seen.find(c) != std::string::npos) return malformed("a flag given twice");
        seen += c;
        extended = extended || c == 'X';
        fd = fd || c == 'F';
    }
    if (value > (extended ? 0x1FFFFFFFu : 0x7FFu))
        return malformed(extended ? "extended id above 0x1FFFFFFF" : "standard id above 0x7FF");
    if (data.size() % 2 != 0) return malformed("odd number of hex digits");
    for (const char c : data)
        if (!isHex(c)) return malformed("data not hex");
    const size_t bytes = data.size() / 2;
    if (bytes > (fd ? 64u : 8u))
        return malformed(fd ? "more than 64 data bytes" : "more than 8 data bytes");
    l.kind = VirtualCanLineKind::Frame;
    l.body = rest;
    return l;
}

} // namespace cutcell::canopen
