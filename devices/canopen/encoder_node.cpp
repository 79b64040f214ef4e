#include "devices/canopen/encoder_node.h"

#include "devices/canopen/emcy.h"
#include "devices/canopen/nmt.h"
#include "devices/canopen/pdo.h"

#include <algorithm>
#include <cmath>

namespace cutcell::canopen {
namespace {
constexpr std::uint32_t kInvalid = 0x80000000u;
constexpr std::uint32_t kPositionEntry = (std::uint32_t{od::kEncoderPositionValue} << 16) | 32;
} // namespace

EncoderNode::EncoderNode(EncoderNodeConfig c) : c_(std::move(c)) {
    resetCommunication();
}

void EncoderNode::resetCommunication() {
    heartbeatMs_ = 0;
    syncOverflow_ = 0;
    // Predefined connection set: TPDO1 valid, the position value mapped (CiA 406 default).
    tpdoCobId_ = cob::kTpdo1 + static_cast<std::uint32_t>(c_.node);
    tpdoType_ = 1;
    mapCount_ = 1;
    mapEntry_ = kPositionEntry;
}

void EncoderNode::boot(double now_s, std::vector<CanFrame>& out) {
    nmt_ = NmtState::PreOperational;
    operationalSince_s_ = -1;
    nextHeartbeat_s_ = now_s;
    out.push_back(encodeHeartbeat(c_.node, NmtState::BootUp));
}

double EncoderNode::measuredAt(double now_s) const {
    if (c_.sync_period_s <= 0 || firstSync_s_ < 0) return now_s;
    return firstSync_s_ + static_cast<double>(syncs_ - 1) * c_.sync_period_s;
}

std::int32_t EncoderNode::sample(double now_s) const {
    const double x = c_.position ? c_.position(measuredAt(now_s)) : 0.0;
    return static_cast<std::int32_t>(
        std::clamp(std::round(x * c_.counts_per_unit), -2147483648.0, 2147483647.0));
}

void EncoderNode::handle(const CanFrame& in, double now_s, std::vector<CanFrame>& out) {
    NmtCommand command;
    int target = 0;
    if (decodeNmt(in, command, target)) {
        if (target != 0 && target != c_.node) return;
        switch (command) {
        case NmtCommand::Start:
            if (nmt_ != NmtState::Operational) operationalSince_s_ = now_s;
            nmt_ = NmtState::Operational;
            break;
        case NmtCommand::Stop:
            nmt_ = NmtState::Stopped;
            operationalSince_s_ = -1;
            break;
        case NmtCommand::EnterPreOperational:
            nmt_ = NmtState::PreOperational;
            operationalSince_s_ = -1;
            break;
        case NmtCommand::ResetNode:
            heartbeatStopped_ = pdoStopped_ = false;
            [[fallthrough]];
        case NmtCommand::ResetCommunication:
            resetCommunication();
            boot(now_s, out);
            break;
        }
        return;
    }
    if (nmt_ == NmtState::Stopped) return;
    if (in.id == cob::kSdoRx + static_cast<std::uint32_t>(c_.node)) {
        onSdo(in, now_s, out);
        return;
    }
    std::uint8_t counter = 0;
    if (nmt_ != NmtState::Operational || !decodeSync(in, counter)) return;
    // A SYNC of the wrong length for 0x1019 (CiA 301): told, not answered. The encoder drives
    // nothing, so the counter's sequence is the drives' to check.
    if ((syncOverflow_ > 0) != (in.len == 1)) {
        out.push_back(encodeEmcy(c_.node, emcy_code::kSyncDataLength,
                                 errorRegisterFor(emcy_code::kSyncDataLength)));
        return;
    }
    if (firstSync_s_ < 0) firstSync_s_ = now_s;
    ++syncs_;
    counts_ = sample(now_s);
    if (pdoStopped_ || (tpdoCobId_ & kInvalid) || tpdoType_ == 0 || tpdoType_ > 240 ||
        mapCount_ != 1)
        return;
    CanFrame f = encodeEncoderTpdo(c_.node, counts_);
    f.id = tpdoCobId_ & 0x7FF;
    out.push_back(f);
}

void EncoderNode::tick(double now_s, std::vector<CanFrame>& out) {
    if (operationalSince_s_ >= 0) {
        const double up = now_s - operationalSince_s_;
        if (c_.heartbeat_stop_after_s >= 0 && up >= c_.heartbeat_stop_after_s)
            heartbeatStopped_ = true;
        if (c_.pdo_stop_after_s >= 0 && up >= c_.pdo_stop_after_s) pdoStopped_ = true;
    }
    if (heartbeatMs_ > 0 && !heartbeatStopped_ && nmt_ != NmtState::BootUp &&
        now_s >= nextHeartbeat_s_) {
        out.push_back(encodeHeartbeat(c_.node, nmt_));
        nextHeartbeat_s_ += heartbeatMs_ * 1e-3;
        if (nextHeartbeat_s_ < now_s) nextHeartbeat_s_ = now_s + heartbeatMs_ * 1e-3;
    }
}

void EncoderNode::onSdo(const CanFrame& in, double now_s, std::vector<CanFrame>& out) {
    const SdoMessage m = decodeSdo(in);
    std::uint32_t value = 0, abort = 0;
    int size = 0;
    switch (m.kind) {
    case SdoKind::UploadRequest:
        abort = read(m.address, value, size, now_s);
        if (!abort) out.push_back(sdoUploadResponse(c_.node, m.address, value, size));
        break;
    case SdoKind::DownloadRequest:
        abort = write(m.address, m.value, m.size);
        if (!abort) out.push_back(sdoDownloadResponse(c_.node, m.address));
        break;
    case SdoKind::Abort:
        return;
    default:
        abort = abort_code::kUnknownCommand;
        break;
    }
    if (abort) out.push_back(sdoAbort(c_.node, m.address, abort, true));
}

std::uint32_t EncoderNode::read(SdoAddress a, std::uint32_t& v, int& size, double now_s) const {
    auto one = [&](std::uint32_t value, int bytes) -> std::uint32_t {
        if (a.sub != 0) return abort_code::kNoSubIndex;
        v = value;
        size = bytes;
        return 0;
    };
    switch (a.index) {
    case od::kDeviceType:
        return one(od::kDeviceTypeCia406, 4);
    case od::kProducerHeartbeat:
        return one(heartbeatMs_, 2);
    case od::kSyncCounterOverflow:
        return one(syncOverflow_, 1);
    case od::kEncoderPositionValue:
        return one(static_cast<std::uint32_t>(sample(now_s)), 4);
    case od::kIdentity:
        if (a.sub > 4) return abort_code::kNoSubIndex;
        v = a.sub == 0   ? 4u
            : a.sub == 1 ? 0x00000CCEu
            : a.sub == 2 ? 0x406u
            : a.sub == 3 ? 1u
                         : static_cast<std::uint32_t>(c_.node);
        size = a.sub == 0 ? 1 : 4;
        return 0;
    case od::kTpdoComm:
        if (a.sub > 2) return abort_code::kNoSubIndex;
        v = a.sub == 0 ? 2u : a.sub == 1 ? tpdoCobId_ : tpdoType_;
        size = a.sub == 1 ? 4 : 1;
        return 0;
    case od::kTpdoMap:
        if (a.sub > 1) return abort_code::kNoSubIndex;
        v = a.sub == 0 ? mapCount_ : mapEntry_;
        size = a.sub == 0 ? 1 : 4;
        return 0;
    default:
        return abort_code::kNoObject;
    }
}

std::uint32_t EncoderNode::write(SdoAddress a, std::uint32_t v, int size) {
    auto sized = [&](int bytes) -> std::uint32_t {
        return size == 0 || size == bytes ? 0 : abort_code::kLengthMismatch;
    };
    std::uint32_t abort = 0;
    switch (a.index) {
    case od::kSyncCounterOverflow:
        if (a.sub != 0) return abort_code::kNoSubIndex;
        if ((abort = sized(1))) return abort;
        if (v == 1 || v > 240) return abort_code::kInvalidValue; // 0, or 2..240 (CiA 301)
        syncOverflow_ = static_cast<std::uint8_t>(v);
        return 0;
    case od::kProducerHeartbeat:
        if (a.sub != 0) return abort_code::kNoSubIndex;
        if ((abort = sized(2))) return abort;
        heartbeatMs_ = static_cast<std::uint16_t>(v);
        nextHeartbeat_s_ = 0;
        return 0;
    case od::kTpdoComm:
        if (a.sub == 0) return abort_code::kReadOnly;
        if (a.sub == 1) {
            if ((abort = sized(4))) return abort;
            if (!(tpdoCobId_ & kInvalid) && !(v & kInvalid) && (v & 0x7FF) != (tpdoCobId_ & 0x7FF))
                return abort_code::kInvalidValue;
            tpdoCobId_ = v & (kInvalid | 0x7FF);
            return 0;
        }
        if (a.sub == 2) {
            if ((abort = sized(1))) return abort;
            if (v == 0 || (v > 1 && v < 254)) return abort_code::kInvalidValue;
            tpdoType_ = static_cast<std::uint8_t>(v);
            return 0;
        }
        return abort_code::kNoSubIndex;
    case od::kTpdoMap:
        if (!(tpdoCobId_ & kInvalid)) return abort_code::kDeviceState;
        if (a.sub == 0) {
            if ((abort = sized(1))) return abort;
            if (v > 1) return abort_code::kValueTooHigh;
            if (v == 1 && mapEntry_ != kPositionEntry) return abort_code::kCannotMap;
            mapCount_ = static_cast<std::uint8_t>(v);
            return 0;
        }
        if (a.sub != 1) return abort_code::kNoSubIndex;
        if ((abort = sized(4))) return abort;
        if (mapCount_ != 0) return abort_code::kDeviceState;
        if (v != kPositionEntry) return abort_code::kCannotMap;
        mapEntry_ = v;
        return 0;
    case od::kDeviceType:
    case od::kIdentity:
    case od::kEncoderPositionValue:
        return abort_code::kReadOnly;
    default:
        return abort_code::kNoObject;
    }
}

} // namespace cutcell::canopen
