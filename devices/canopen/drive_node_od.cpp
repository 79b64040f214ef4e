// The object-dictionary subset of the simulated drive: what an SDO may read and write, with
// the CiA 301 abort codes a real drive gives for wrong accesses.
#include "devices/canopen/drive_node.h"
#include "devices/canopen/emcy.h"
#include "devices/canopen/pdo.h"

#include <cmath>

namespace cutcell::canopen {
namespace {

constexpr std::uint32_t kVendorId = 0x00000CCE; // a simulator, not a registered vendor
constexpr std::uint32_t kProductCode = 0x00000402;

// Size check of an expedited download: 0 = size not indicated (accepted).
std::uint32_t sizeCheck(int given, int expected) {
    return given == 0 || given == expected ? 0 : abort_code::kLengthMismatch;
}

struct Mappable {
    std::uint16_t index;
    std::uint8_t bits;
    bool rx; // may be mapped into an RPDO (else a TPDO)
};
constexpr Mappable kMappable[] = {
    {od::kControlword, 16, true},     {od::kTargetPosition, 32, true},
    {od::kModesOfOperation, 8, true}, {od::kStatusword, 16, false},
    {od::kPositionActual, 32, false}, {od::kModesDisplay, 8, false},
    {od::kErrorCode, 16, false},      {od::kTorqueActual, 16, false},
    {od::kTargetTorque, 16, true},
};

bool mappable(std::uint32_t entry, bool rx) {
    const auto index = static_cast<std::uint16_t>(entry >> 16);
    const auto sub = static_cast<std::uint8_t>((entry >> 8) & 0xFF);
    const auto bits = static_cast<std::uint8_t>(entry & 0xFF);
    for (const Mappable& m : kMappable)
        if (m.index == index && sub == 0 && m.bits == bits && m.rx == rx) return true;
    return false;
}

} // namespace

std::uint32_t DriveNode::read(SdoAddress a, std::uint32_t& v, int& size) const {
    auto one = [&](std::uint32_t value, int bytes) -> std::uint32_t {
        if (a.sub != 0) return abort_code::kNoSubIndex;
        v = value;
        size = bytes;
        return 0;
    };
    switch (a.index) {
    case od::kDeviceType:
        return one(od::kDeviceTypeCia402, 4);
    case od::kErrorRegister:
        return one(errorRegisterFor(errorCode_), 1);
    case od::kCommCyclePeriod:
        return one(cyclePeriodUs_, 4);
    case od::kSyncCounterOverflow:
        return one(syncOverflow_, 1);
    case od::kProducerHeartbeat:
        return one(heartbeatMs_, 2);
    case od::kConsumerHeartbeat:
        if (a.sub > 1) return abort_code::kNoSubIndex;
        v = a.sub == 0 ? 1 : consumerHeartbeat_;
        size = a.sub == 0 ? 1 : 4;
        return 0;
    case od::kAbortConnectionOption:
        return one(static_cast<std::uint16_t>(abortConnectionOption_), 2);
    case od::kIdentity:
        size = a.sub == 0 ? 1 : 4;
        switch (a.sub) {
        case 0:
            v = 4;
            return 0;
        case 1:
            v = kVendorId;
            return 0;
        case 2:
            v = kProductCode;
            return 0;
        case 3:
            v = 1;
            return 0;
        case 4:
            v = static_cast<std::uint32_t>(cfg_.node);
            return 0;
        default:
            return abort_code::kNoSubIndex;
        }
    case od::kErrorCode:
        return one(errorCode_, 2);
    case od::kControlword:
        return one(controlword_, 2);
    case od::kStatusword:
        return one(statusword(), 2);
    case od::kQuickStopOption:
        return one(static_cast<std::uint16_t>(quickStopOption_), 2);
    case od::kModesOfOperation:
    case od::kModesDisplay:
        return one(static_cast<std::uint8_t>(mode_), 1);
    case od::kPositionActual:
        return one(static_cast<std::uint32_t>(actualCounts()), 4);
    case od::kFollowingErrorWindow:
        return one(followingWindow_, 4);
    case od::kTargetPosition:
        return one(static_cast<std::uint32_t>(targetCounts_), 4);
    case od::kQuickStopDecel:
        return one(quickStopDecel_, 4);
    case od::kMotorRatedTorque:
        return one(static_cast<std::uint32_t>(std::lround(ratedTorque() * 1000)), 4);
    case od::kTargetTorque:
        return one(static_cast<std::uint16_t>(targetTorque_), 2);
    case od::kTorqueActual: {
        const double limit = ratedTorque();
        const long permille = limit > 0 ? std::lround(lastTorque_ / limit * 1000) : 0;
        return one(static_cast<std::uint16_t>(static_cast<std::int16_t>(permille)), 2);
    }
    default:
        break;
    }
    const Pdo* p = const_cast<DriveNode*>(this)->pdoFor(a.index);
    if (!p) return abort_code::kNoObject;
    const bool comm = (a.index & 0x0200) == 0; // 0x14xx / 0x18xx vs 0x16xx / 0x1Axx
    if (comm) {
        switch (a.sub) {
        case 0:
            v = 2;
            size = 1;
            return 0;
        case 1:
            v = p->cob_id;
            size = 4;
            return 0;
        case 2:
            v = p->type;
            size = 1;
            return 0;
        default:
            return abort_code::kNoSubIndex;
        }
    }
    if (a.sub == 0) {
        v = p->count;
        size = 1;
        return 0;
    }
    if (a.sub > 8) return abort_code::kNoSubIndex;
    v = p->map[a.sub - 1u];
    size = 4;
    return 0;
}

std::uint32_t DriveNode::write(SdoAddress a, std::uint32_t v, int size, double now_s,
                               std::vector<CanFrame>& out) {
    auto scalar = [&](int bytes) -> std::uint32_t {
        if (a.sub != 0) return abort_code::kNoSubIndex;
        return sizeCheck(size, bytes);
    };
    std::uint32_t abort = 0;
    if (cfg_.faults.refuse_sdo_index != 0 && a.index == cfg_.faults.refuse_sdo_index)
        return abort_code::kInvalidValue;
    switch (a.index) {
    case od::kDeviceType:
    case od::kErrorRegister:
    case od::kIdentity:
    case od::kErrorCode:
    case od::kStatusword:
    case od::kModesDisplay:
    case od::kPositionActual:
    case od::kMotorRatedTorque:
    case od::kTorqueActual:
        if ((abort = read(a, v, size))) return abort;
        return abort_code::kReadOnly;
    case od::kCommCyclePeriod:
        if ((abort = scalar(4))) return abort;
        if (v < 100) return abort_code::kValueTooLow;     // < 100 us: no position loop fits
        if (v > 100000) return abort_code::kValueTooHigh; // > 100 ms: not a servo cycle
        cyclePeriodUs_ = v;
        return 0;
    case od::kSyncCounterOverflow:
        if ((abort = scalar(1))) return abort;
        if (v == 1 || v > 240) return abort_code::kInvalidValue; // 0, or 2..240 (CiA 301)
        syncOverflow_ = static_cast<std::uint8_t>(v);
        lastSyncCounter_ = 0;
        return 0;
    case od::kProducerHeartbeat:
        if ((abort = scalar(2))) return abort;
        heartbeatMs_ = static_cast<std::uint16_t>(v);
        nextHeartbeat_s_ = 0; // start producing at once
        return 0;
    case od::kConsumerHeartbeat:
        if (a.sub == 0) return abort_code::kReadOnly;
        if (a.sub > 1) return abort_code::kNoSubIndex;
        if ((abort = sizeCheck(size, 4))) return abort;
        if ((v >> 16) > 127) return abort_code::kInvalidValue; // producer node id 0..127
        consumerHeartbeat_ = v & 0x00FFFFFFu;
        consumerLastSeen_s_ = -1; // armed by the producer's next heartbeat
        consumerLost_ = false;
        return 0;
    case od::kAbortConnectionOption:
        if ((abort = scalar(2))) return abort;
        if (static_cast<std::int16_t>(v) < 0 || v > 3) return abort_code::kInvalidValue;
        abortConnectionOption_ = static_cast<std::int16_t>(v);
        return 0;
    case od::kControlword:
        if ((abort = scalar(2))) return abort;
        setControlword(static_cast<std::uint16_t>(v), now_s, out);
        return 0;
    case od::kQuickStopOption:
        if ((abort = scalar(2))) return abort;
        if (v != 2 && v != 6) return abort_code::kInvalidValue; // slow down, then disable / stay
        quickStopOption_ = static_cast<std::int16_t>(v);
        return 0;
    case od::kModesOfOperation: {
        if ((abort = scalar(1))) return abort;
        const auto m = static_cast<std::int8_t>(v);
        if (m != kModeCyclicSyncPosition && m != kModeCyclicSyncTorque)
            return abort_code::kInvalidValue;
        // The mode changes only without torque (a running axis keeps its mode).
        if (m != mode_ && state_ == Cia402State::OperationEnabled) return abort_code::kDeviceState;
        mode_ = m;
        return 0;
    }
    case od::kTargetTorque:
        if ((abort = scalar(2))) return abort;
        targetTorque_ = static_cast<std::int16_t>(v);
        return 0;
    case od::kFollowingErrorWindow:
        if ((abort = scalar(4))) return abort;
        if (v == 0) return abort_code::kValueTooLow;
        followingWindow_ = v;
        return 0;
    case od::kTargetPosition:
        if ((abort = scalar(4))) return abort;
        targetCounts_ = static_cast<std::int32_t>(v);
        return 0;
    case od::kQuickStopDecel:
        if ((abort = scalar(4))) return abort;
        if (v == 0) return abort_code::kValueTooLow;
        quickStopDecel_ = v;
        return 0;
    default:
        break;
    }
    Pdo* p = pdoFor(a.index);
    if (!p) return abort_code::kNoObject;
    const bool rx = (a.index & 0xFE00) == 0x1400 || (a.index & 0xFE00) == 0x1600;
    const bool comm = (a.index & 0x0200) == 0;
    if (comm) {
        switch (a.sub) {
        case 0:
            return abort_code::kReadOnly;
        case 1:
            if ((abort = sizeCheck(size, 4))) return abort;
            // A valid PDO's COB-ID may only change by invalidating it first.
            if (p->valid() && !(v & Pdo::kInvalid) && (v & 0x7FF) != (p->cob_id & 0x7FF))
                return abort_code::kInvalidValue;
            p->cob_id = v & (Pdo::kInvalid | 0x7FF);
            return 0;
        case 2:
            if ((abort = sizeCheck(size, 1))) return abort;
            if (v == 0 || (v > 1 && v < 254)) return abort_code::kInvalidValue; // 1, 254, 255 only
            p->type = static_cast<std::uint8_t>(v);
            return 0;
        default:
            return abort_code::kNoSubIndex;
        }
    }
    if (p->valid()) return abort_code::kDeviceState; // mapping changes need an invalid PDO
    if (a.sub == 0) {
        if ((abort = sizeCheck(size, 1))) return abort;
        if (v > 8) return abort_code::kValueTooHigh;
        int bits = 0;
        for (std::uint32_t i = 0; i < v; ++i) {
            if (!mappable(p->map[i], rx)) return abort_code::kCannotMap;
            bits += static_cast<int>(p->map[i] & 0xFF);
        }
        if (bits > 64) return abort_code::kPdoTooLong;
        p->count = static_cast<std::uint8_t>(v);
        return 0;
    }
    if (a.sub > 8) return abort_code::kNoSubIndex;
    if ((abort = sizeCheck(size, 4))) return abort;
    if (p->count != 0) return abort_code::kDeviceState; // sub 0 must be 0 while mapping
    if (!mappable(v, rx)) return abort_code::kCannotMap;
    p->map[a.sub - 1u] = v;
    return 0;
}

} // namespace cutcell::canopen
