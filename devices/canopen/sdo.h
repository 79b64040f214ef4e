#pragma once
// CANopen SDO, expedited transfers only (objects of 1..4 bytes; all a CiA 402 start-up needs),
// CiA 301 section 7.2.4. Client requests go to 0x600 + node, server answers come from 0x580 + node.
#include "devices/canopen/can_frame.h"

#include <cstdint>
#include <optional>
#include <string>

namespace cutcell::canopen {

struct SdoAddress {
    std::uint16_t index = 0;
    std::uint8_t sub = 0;
    bool operator==(const SdoAddress&) const = default;
};

// Client side.
CanFrame sdoUploadRequest(int node, SdoAddress a);
CanFrame sdoDownloadRequest(int node, SdoAddress a, std::uint32_t value, int size);
// Server side.
CanFrame sdoUploadResponse(int node, SdoAddress a, std::uint32_t value, int size);
CanFrame sdoDownloadResponse(int node, SdoAddress a);
CanFrame sdoAbort(int node, SdoAddress a, std::uint32_t abortCode, bool fromServer);

enum class SdoKind : std::uint8_t {
    UploadRequest,
    DownloadRequest,
    UploadResponse,
    DownloadResponse,
    Abort,
    Unsupported, // segmented / block transfers, or a malformed frame
};

struct SdoMessage {
    SdoKind kind = SdoKind::Unsupported;
    SdoAddress address;
    std::uint32_t value = 0; // data (download request, upload response) or abort code
    int size = 0;            // bytes of data, 0 when not indicated
};

// Decodes the 8 data bytes of an SDO frame (either direction).
SdoMessage decodeSdo(const CanFrame& f);

// CiA 301 abort codes as text ("0x06020000: object does not exist in the object dictionary").
std::string sdoAbortText(std::uint32_t code);

namespace abort_code {
inline constexpr std::uint32_t kTimeout = 0x05040000;
inline constexpr std::uint32_t kUnknownCommand = 0x05040001;
inline constexpr std::uint32_t kUnsupportedAccess = 0x06010000;
inline constexpr std::uint32_t kWriteOnly = 0x06010001;
inline constexpr std::uint32_t kReadOnly = 0x06010002;
inline constexpr std::uint32_t kNoObject = 0x06020000;
inline constexpr std::uint32_t kCannotMap = 0x06040041;
inline constexpr std::uint32_t kPdoTooLong = 0x06040042;
inline constexpr std::uint32_t kLengthMismatch = 0x06070010;
inline constexpr std::uint32_t kNoSubIndex = 0x06090011;
inline constexpr std::uint32_t kInvalidValue = 0x06090030;
inline constexpr std::uint32_t kValueTooHigh = 0x06090031;
inline constexpr std::uint32_t kValueTooLow = 0x06090032;
inline constexpr std::uint32_t kGeneral = 0x08000000;
inline constexpr std::uint32_t kDeviceState = 0x08000022;
} // namespace abort_code

} // namespace cutcell::canopen
