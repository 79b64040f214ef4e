#include "devices/canopen/emcy.h"
#include "core/common/c_format.h"

#include <cstdio>

namespace cutcell::canopen {

CanFrame encodeEmcy(int node, std::uint16_t errorCode, std::uint8_t errorRegister) {
    CanFrame f;
    f.id = cob::kEmcy + static_cast<std::uint32_t>(node);
    f.len = 8;
    putU16(f, 0, errorCode);
    f.data[2] = errorRegister;
    return f;
}

bool decodeEmcy(const CanFrame& f, Emcy& out) {
    if (cob::functionOf(f.id) != cob::kEmcy || cob::nodeOf(f.id) == 0 || f.len != 8) return false;
    out.node = cob::nodeOf(f.id);
    out.error_code = getU16(f, 0);
    out.error_register = f.data[2];
    return true;
}

namespace {

struct Entry {
    std::uint16_t code;
    std::uint16_t mask; // 0xFFFF exact code, 0xFF00 / 0xF000 a class
    const char* text;
};

// Most specific first: exact codes, then sub-classes (xx00), then classes (x000).
constexpr Entry kTable[] = {
    {0x0000, 0xFFFF, "error reset or no error"},
    {0x2310, 0xFFFF, "continuous over-current"},
    {0x2320, 0xFFFF, "short circuit or earth leakage"},
    {0x3210, 0xFFFF, "DC link over-voltage"},
    {0x3220, 0xFFFF, "DC link under-voltage"},
    {0x4210, 0xFFFF, "excess temperature, device"},
    {0x4310, 0xFFFF, "excess temperature, drive"},
    {0x5530, 0xFFFF, "data storage (non-volatile memory)"},
    {0x7121, 0xFFFF, "motor blocked"},
    {0x7305, 0xFFFF, "incremental sensor 1 fault"},
    {0x8110, 0xFFFF, "CAN overrun (objects lost)"},
    {0x8120, 0xFFFF, "CAN in error passive mode"},
    {0x8130, 0xFFFF, "life guard or heartbeat error"},
    {0x8140, 0xFFFF, "recovered from bus off"},
    {0x8150, 0xFFFF, "CAN-ID collision"},
    {0x8210, 0xFFFF, "PDO not processed due to length error"},
    {0x8220, 0xFFFF, "PDO length exceeded"},
    {0x8240, 0xFFFF, "unexpected SYNC data length"},
    {0x8250, 0xFFFF, "RPDO timeout"},
    {0x8611, 0xFFFF, "following error"},
    {0x8612, 0xFFFF, "reference limit"},
    {0x2100, 0xFF00, "current, device input side"},
    {0x2200, 0xFF00, "current inside the device"},
    {0x2300, 0xFF00, "current, device output side"},
    {0x3100, 0xFF00, "mains voltage"},
    {0x3200, 0xFF00, "voltage inside the device"},
    {0x3300, 0xFF00, "output voltage"},
    {0x4100, 0xFF00, "ambient temperature"},
    {0x4200, 0xFF00, "device temperature"},
    {0x4300, 0xFF00, "drive temperature"},
    {0x6100, 0xFF00, "internal software"},
    {0x6200, 0xFF00, "user software"},
    {0x6300, 0xFF00, "data set"},
    {0x7100, 0xFF00, "power (motor)"},
    {0x7300, 0xFF00, "sensor"},
    {0x8100, 0xFF00, "communication"},
    {0x8200, 0xFF00, "protocol error"},
    {0x8300, 0xFF00, "torque control"},
    {0x8400, 0xFF00, "velocity speed controller"},
    {0x8500, 0xFF00, "position controller"},
    {0x8600, 0xFF00, "positioning controller"},
    {0x1000, 0xF000, "generic error"},
    {0x2000, 0xF000, "current"},
    {0x3000, 0xF000, "voltage"},
    {0x4000, 0xF000, "temperature"},
    {0x5000, 0xF000, "device hardware"},
    {0x6000, 0xF000, "device software"},
    {0x7000, 0xF000, "additional modules"},
    {0x8000, 0xF000, "monitoring"},
    {0x9000, 0xF000, "external error"},
    {0xF000, 0xF000, "additional functions"},
};

} // namespace

std::string emcyText(std::uint16_t code) {
    const unsigned c = code;
    if ((code & 0xFF00) == 0xFF00) return messageC("0x%04X device specific", c);
    for (const Entry& e : kTable) {
        if ((code & e.mask) != e.code) continue;
        const bool exact = e.mask == 0xFFFF || (code & static_cast<std::uint16_t>(~e.mask)) == 0;
        return messageC(exact ? "0x%04X %s" : "0x%04X %s (class)", c, e.text);
    }
    return messageC("0x%04X unknown error code", c);
}

std::uint8_t errorRegisterFor(std::uint16_t code) {
    if (code == 0) return 0;
    std::uint8_t r = error_register::kGeneric;
    switch (code & 0xF000) {
    case 0x2000:
        r |= error_register::kCurrent;
        break;
    case 0x3000:
        r |= error_register::kVoltage;
        break;
    case 0x4000:
        r |= error_register::kTemperature;
        break;
    case 0x8000:
        r |= (code & 0xFF00) == 0x8100 ? error_register::kCommunication : error_register::kProfile;
        break;
    default:
        break;
    }
    return r;
}

} // namespace cutcell::canopen
