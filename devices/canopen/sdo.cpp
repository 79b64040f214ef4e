#include "devices/canopen/sdo.h"
#include "core/common/c_format.h"

#include <cstdio>

namespace cutcell::canopen {
namespace {

CanFrame sdoFrame(std::uint32_t id, std::uint8_t command, SdoAddress a) {
    CanFrame f;
    f.id = id;
    f.len = 8; // SDO frames always carry 8 bytes
    f.data[0] = command;
    putU16(f, 1, a.index);
    f.data[3] = a.sub;
    return f;
}

std::uint32_t masked(std::uint32_t value, int size) {
    return size >= 4 ? value : value & ((1u << (8 * size)) - 1u);
}

// Expedited command byte: specifier in bits 7..5, n (unused bytes) in 3..2, e and s set.
std::uint8_t expedited(std::uint8_t specifier, int size) {
    return static_cast<std::uint8_t>((specifier << 5) | ((4 - size) << 2) | 0x03);
}

} // namespace

CanFrame sdoUploadRequest(int node, SdoAddress a) {
    return sdoFrame(cob::kSdoRx + static_cast<std::uint32_t>(node), 0x40, a);
}

CanFrame sdoDownloadRequest(int node, SdoAddress a, std::uint32_t value, int size) {
    CanFrame f = sdoFrame(cob::kSdoRx + static_cast<std::uint32_t>(node), expedited(1, size), a);
    putU32(f, 4, masked(value, size));
    return f;
}

CanFrame sdoUploadResponse(int node, SdoAddress a, std::uint32_t value, int size) {
    CanFrame f = sdoFrame(cob::kSdoTx + static_cast<std::uint32_t>(node), expedited(2, size), a);
    putU32(f, 4, masked(value, size));
    return f;
}

CanFrame sdoDownloadResponse(int node, SdoAddress a) {
    return sdoFrame(cob::kSdoTx + static_cast<std::uint32_t>(node), 0x60, a);
}

CanFrame sdoAbort(int node, SdoAddress a, std::uint32_t code, bool fromServer) {
    const std::uint32_t base = fromServer ? cob::kSdoTx : cob::kSdoRx;
    CanFrame f = sdoFrame(base + static_cast<std::uint32_t>(node), 0x80, a);
    putU32(f, 4, code);
    return f;
}

SdoMessage decodeSdo(const CanFrame& f) {
    SdoMessage m;
    if (f.len != 8) return m;
    m.address = {getU16(f, 1), f.data[3]};
    const std::uint8_t c = f.data[0];
    const bool fromServer = cob::functionOf(f.id) == cob::kSdoTx;
    const int specifier = c >> 5;
    if (c == 0x80) {
        m.kind = SdoKind::Abort;
        m.value = getU32(f, 4);
        return m;
    }
    const bool isExpedited = (c & 0x02) != 0;
    const bool sizeIndicated = (c & 0x01) != 0;
    const int size = sizeIndicated ? 4 - ((c >> 2) & 0x03) : 0;
    if (!fromServer) {
        if (specifier == 2) {
            m.kind = SdoKind::UploadRequest;
        } else if (specifier == 1 && isExpedited) {
            m.kind = SdoKind::DownloadRequest;
            m.size = size;
            m.value = masked(getU32(f, 4), size == 0 ? 4 : size);
        }
    } else {
        if (specifier == 3) {
            m.kind = SdoKind::DownloadResponse;
        } else if (specifier == 2 && isExpedited) {
            m.kind = SdoKind::UploadResponse;
            m.size = size;
            m.value = masked(getU32(f, 4), size == 0 ? 4 : size);
        }
    }
    return m;
}

std::string sdoAbortText(std::uint32_t code) {
    struct Entry {
        std::uint32_t code;
        const char* text;
    };
    static constexpr Entry kTable[] = {
        {0x05030000, "toggle bit not alternated"},
        {0x05040000, "SDO protocol timed out"},
        {0x05040001, "client/server command specifier not valid or unknown"},
        {0x05040002, "invalid block size"},
        {0x05040003, "invalid sequence number"},
        {0x05040004, "CRC error"},
        {0x05040005, "out of memory"},
        {0x06010000, "unsupported access to an object"},
        {0x06010001, "attempt to read a write-only object"},
        {0x06010002, "attempt to write a read-only object"},
        {0x06020000, "object does not exist in the object dictionary"},
        {0x06040041, "object cannot be mapped to the PDO"},
        {0x06040042,
         "the number and length of the objects to be mapped would exceed the PDO length"},
        {0x06040043, "general parameter incompatibility"},
        {0x06040047, "general internal incompatibility in the device"},
        {0x06060000, "access failed due to a hardware error"},
        {0x06070010, "data type does not match, length of service parameter does not match"},
        {0x06070012, "data type does not match, length of service parameter too high"},
        {0x06070013, "data type does not match, length of service parameter too low"},
        {0x06090011, "sub-index does not exist"},
        {0x06090030, "invalid value for parameter"},
        {0x06090031, "value of parameter written too high"},
        {0x06090032, "value of parameter written too low"},
        {0x06090036, "maximum value is less than minimum value"},
        {0x060A0023, "resource not available: SDO connection"},
        {0x08000000, "general error"},
        {0x08000020, "data cannot be transferred or stored to the application"},
        {0x08000021,
         "data cannot be transferred or stored to the application because of local control"},
        {0x08000022, "data cannot be transferred or stored to the application because of the "
                     "present device state"},
        {0x08000023,
         "object dictionary dynamic generation failed or no object dictionary is present"},
        {0x08000024, "no data available"},
    };
    const unsigned c = code;
    for (const Entry& e : kTable)
        if (e.code == code) return messageC("0x%08X: %s", c, e.text);
    return messageC("0x%08X: unknown abort code", c);
}

} // namespace cutcell::canopen
