#include "devices/canopen/drive_node.h"

#include "devices/canopen/emcy.h"
#include "devices/canopen/pdo.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cutcell::canopen {

double countsPerRad(double countsPerUnit, bool linear) {
    return linear ? countsPerUnit : countsPerUnit * 180.0 / std::numbers::pi;
}

DriveNode::DriveNode(const DriveNodeConfig& c) : cfg_(c), mech_(c.mechanics) {
    followingWindow_ = c.following_error_window_counts > 0
                           ? c.following_error_window_counts
                           : static_cast<std::uint32_t>(
                                 std::lround(5 * std::numbers::pi / 180 * c.counts_per_rad));
    quickStopDecel_ =
        static_cast<std::uint32_t>(std::lround(c.quick_stop_decel_rad_s2 * c.counts_per_rad));
    cyclePeriodUs_ = static_cast<std::uint32_t>(std::lround(c.max_loop_period_s * 1e6));
    loopPeriod_ = c.max_loop_period_s;
    pid_.configure(c.gains, loopPeriod_);
    plant_.configure(c.plant, loopPeriod_);
    plant_.setState(c.start_position_rad, 0);
    cycleTargetRad_ = previousTargetRad_ = plantPosition();
    targetCounts_ = actualCounts();
    updateBrake();
    resetCommunication();
}

void DriveNode::updateBrake() {
    if (mech_)
        mech_->setHeld(state_ != Cia402State::OperationEnabled &&
                       state_ != Cia402State::QuickStopActive);
}

void DriveNode::resetCommunication() {
    heartbeatMs_ = 0;
    syncOverflow_ = 0;
    lastSyncCounter_ = 0;
    consumerHeartbeat_ = 0;
    consumerLastSeen_s_ = -1;
    consumerLost_ = false;
    rpdo_ = {};
    tpdo_ = {};
    rpdoPending_ = {};
    // Predefined connection set defaults: valid PDOs, nothing mapped.
    rpdo_[0].cob_id = cob::kRpdo1 + static_cast<std::uint32_t>(cfg_.node);
    rpdo_[1].cob_id = cob::kRpdo2 + static_cast<std::uint32_t>(cfg_.node);
    tpdo_[0].cob_id = cob::kTpdo1 + static_cast<std::uint32_t>(cfg_.node);
    rpdo_[1].type = kTransmissionEvent;
}

void DriveNode::boot(double now_s, std::vector<CanFrame>& out) {
    nmt_ = NmtState::PreOperational;
    operationalSince_s_ = -1;
    nextHeartbeat_s_ = now_s;
    lastAdvance_s_ = now_s;
    lastSync_s_ = -1;
    out.push_back(encodeHeartbeat(cfg_.node, NmtState::BootUp));
}

void DriveNode::handle(const CanFrame& in, double now_s, std::vector<CanFrame>& out) {
    const auto node = static_cast<std::uint32_t>(cfg_.node);
    NmtCommand command;
    int target = 0;
    if (decodeNmt(in, command, target)) {
        if (target == 0 || target == cfg_.node) onNmt(command, now_s, out);
        return;
    }
    int producer = 0;
    NmtState producerState;
    if (decodeHeartbeat(in, producer, producerState)) {
        if (consumerHeartbeat_ != 0 && producer == static_cast<int>(consumerHeartbeat_ >> 16)) {
            consumerLastSeen_s_ = now_s;
            consumerLost_ = false;
        }
        return;
    }
    if (nmt_ == NmtState::Stopped) return;
    if (in.id == cob::kSdoRx + node) {
        onSdo(in, out);
        return;
    }
    if (nmt_ != NmtState::Operational) return;
    if (std::uint8_t counter = 0; decodeSync(in, counter)) {
        if (syncInSequence(in, counter, now_s, out)) onSync(now_s, out);
        return;
    }
    for (int i = 0; i < 2; ++i)
        if (rpdo_[static_cast<size_t>(i)].valid() &&
            in.id == (rpdo_[static_cast<size_t>(i)].cob_id & 0x7FF))
            onRpdo(i, in, now_s, out);
}

void DriveNode::superviseMaster(double now_s, std::vector<CanFrame>& out) {
    const double timeout = (consumerHeartbeat_ & 0xFFFF) * 1e-3;
    if (consumerLost_ || consumerLastSeen_s_ < 0 || timeout <= 0 ||
        now_s - consumerLastSeen_s_ <= timeout)
        return;
    consumerLost_ = true;
    abortConnection(emcy_code::kHeartbeat, now_s, out);
}

bool DriveNode::syncInSequence(const CanFrame& in, std::uint8_t counter, double now_s,
                               std::vector<CanFrame>& out) {
    // CiA 301: with 0x1019 set every SYNC carries the counter, without it none does.
    if ((syncOverflow_ > 0) != (in.len == 1)) {
        abortConnection(emcy_code::kSyncDataLength, now_s, out);
        return false;
    }
    if (syncOverflow_ == 0) return true;
    const bool first = lastSyncCounter_ == 0;
    const std::uint8_t expected = nextSyncCounter(lastSyncCounter_, syncOverflow_);
    lastSyncCounter_ = counter;
    if (first || counter == expected) return true;
    // Skipped or repeated: a second SYNC producer or lost frames - the cycle is not the
    // master's any more. No actuation on it; the 0x6007 reaction.
    abortConnection(emcy_code::kCommunication, now_s, out);
    return false;
}

void DriveNode::abortConnection(std::uint16_t code, double now_s, std::vector<CanFrame>& out) {
    out.push_back(encodeEmcy(cfg_.node, code, errorRegisterFor(code)));
    const bool powered = state_ == Cia402State::OperationEnabled ||
                         state_ == Cia402State::SwitchedOn ||
                         state_ == Cia402State::ReadyToSwitchOn;
    switch (abortConnectionOption_) {
    case abort_connection::kFault:
        if (state_ != Cia402State::Fault) raiseFault(code, out);
        break;
    case abort_connection::kDisableVoltage:
        if (powered) enterState(Cia402State::SwitchOnDisabled, now_s);
        break;
    case abort_connection::kQuickStop:
        if (state_ == Cia402State::OperationEnabled)
            enterState(Cia402State::QuickStopActive, now_s);
        else if (powered)
            enterState(Cia402State::SwitchOnDisabled, now_s);
        break;
    default:
        break;
    }
    if (nmt_ == NmtState::Operational) {
        nmt_ = NmtState::PreOperational;
        operationalSince_s_ = -1;
    }
}

void DriveNode::tick(double now_s, std::vector<CanFrame>& out) {
    superviseMaster(now_s, out);
    const FaultInjection& f = cfg_.faults;
    if (f.heartbeat_stop_after_s >= 0 && operationalSince_s_ >= 0 &&
        now_s - operationalSince_s_ >= f.heartbeat_stop_after_s)
        heartbeatStopped_ = true;
    if (heartbeatMs_ > 0 && !heartbeatStopped_ && nmt_ != NmtState::BootUp &&
        now_s >= nextHeartbeat_s_) {
        out.push_back(encodeHeartbeat(cfg_.node, nmt_));
        nextHeartbeat_s_ += heartbeatMs_ * 1e-3;
        if (nextHeartbeat_s_ < now_s) nextHeartbeat_s_ = now_s + heartbeatMs_ * 1e-3; // fell behind
    }
    const double cycle = cyclePeriodUs_ * 1e-6;
    if (state_ == Cia402State::OperationEnabled && lastSync_s_ >= 0 &&
        now_s - lastSync_s_ > std::max(0.1, 20 * cycle))
        raiseFault(0x8250, out); // RPDO timeout: the master stopped the cycle
    if (lastAdvance_s_ >= 0 && state_ != Cia402State::OperationEnabled &&
        (lastSync_s_ < 0 || now_s - lastSync_s_ > 3 * cycle)) {
        // Free-running position loop at its own period while no SYNC comes (stopping, coasting).
        // Not while following: a SYNC-paced run may be faster than the wall clock (lock-step).
        const int steps = std::min(50, static_cast<int>((now_s - lastAdvance_s_) / loopPeriod_));
        if (steps > 0) {
            previousTargetRad_ = cycleTargetRad_;
            advance(steps, loopPeriod_, out);
            lastAdvance_s_ = std::max(lastAdvance_s_ + steps * loopPeriod_, now_s - 0.05);
        }
    }
    if (state_ == Cia402State::OperationEnabled && enabledSince_s_ >= 0) {
        const double enabled = now_s - enabledSince_s_;
        if (f.fault_code != 0 && f.fault_after_s >= 0 && enabled >= f.fault_after_s) {
            const std::uint16_t code = f.fault_code;
            cfg_.faults.fault_code = 0; // one shot: a reset drive runs again
            raiseFault(code, out);
        }
        if (f.torque_loss_after_s >= 0 && enabled >= f.torque_loss_after_s) {
            cfg_.faults.torque_loss_after_s = -1;
            torqueLost_ = true;
        }
    }
}

void DriveNode::onNmt(NmtCommand c, double now_s, std::vector<CanFrame>& out) {
    switch (c) {
    case NmtCommand::Start:
        if (nmt_ != NmtState::Operational) operationalSince_s_ = now_s;
        lastSyncCounter_ = 0; // the counter's first SYNC of this session starts it
        nmt_ = NmtState::Operational;
        break;
    case NmtCommand::Stop:
    case NmtCommand::EnterPreOperational:
        // Losing Operational while enabled: the drive stops itself (abort connection option).
        if (state_ == Cia402State::OperationEnabled)
            enterState(Cia402State::QuickStopActive, now_s);
        nmt_ = c == NmtCommand::Stop ? NmtState::Stopped : NmtState::PreOperational;
        operationalSince_s_ = -1;
        break;
    case NmtCommand::ResetNode:
        enterState(Cia402State::SwitchOnDisabled, now_s);
        errorCode_ = 0;
        followingError_ = torqueLost_ = heartbeatStopped_ = false;
        controlword_ = 0;
        resetCommunication();
        boot(now_s, out);
        break;
    case NmtCommand::ResetCommunication:
        // Leaves Operational too (through boot-up to pre-operational): no torque behind the
        // master's back while nobody commands the drive.
        if (state_ == Cia402State::OperationEnabled)
            enterState(Cia402State::QuickStopActive, now_s);
        resetCommunication();
        boot(now_s, out);
        break;
    }
}

void DriveNode::onSdo(const CanFrame& in, std::vector<CanFrame>& out) {
    const SdoMessage m = decodeSdo(in);
    std::uint32_t value = 0;
    int size = 0;
    std::uint32_t abort = 0;
    switch (m.kind) {
    case SdoKind::UploadRequest:
        abort = read(m.address, value, size);
        if (!abort) out.push_back(sdoUploadResponse(cfg_.node, m.address, value, size));
        break;
    case SdoKind::DownloadRequest:
        abort = write(m.address, m.value, m.size, -1, out);
        if (!abort) out.push_back(sdoDownloadResponse(cfg_.node, m.address));
        break;
    case SdoKind::Abort:
        return; // client gave up: nothing to answer
    default:
        abort = abort_code::kUnknownCommand;
        break;
    }
    if (abort) out.push_back(sdoAbort(cfg_.node, m.address, abort, true));
}

void DriveNode::onSync(double now_s, std::vector<CanFrame>& out) {
    // A cycle's deferred loop steps are all run before the next SYNC samples.
    while (hasDeferredStep())
        runDeferredStep(out);
    ++syncs_;
    lastSync_s_ = now_s;
    // 1. Sample: TPDOs carry the state at the SYNC instant.
    for (const Pdo& p : tpdo_) {
        if (!p.valid() || p.type == 0 || p.type > 240) continue;
        CanFrame f;
        f.id = p.cob_id & 0x7FF;
        int byte = 0;
        for (int i = 0; i < p.count; ++i) {
            const std::uint32_t e = p.map[static_cast<size_t>(i)];
            std::uint32_t v = 0;
            int size = 0;
            read({static_cast<std::uint16_t>(e >> 16), static_cast<std::uint8_t>(e >> 8)}, v, size);
            for (int b = 0; b < static_cast<int>((e & 0xFF) / 8); ++b)
                f.data[static_cast<size_t>(byte++)] = static_cast<std::uint8_t>(v >> (8 * b));
        }
        f.len = static_cast<std::uint8_t>(byte);
        out.push_back(f);
    }
    // 2. Actuate: the RPDO data received since the last SYNC takes effect.
    for (int i = 0; i < 2; ++i)
        if (rpdoPending_[static_cast<size_t>(i)]) applyRpdoData(i, now_s, out);
    previousTargetRad_ = cycleTargetRad_;
    if (state_ == Cia402State::OperationEnabled)
        cycleTargetRad_ = targetCounts_ / cfg_.counts_per_rad;
    // 3. Move over the next communication cycle.
    tick(now_s, out);
    const double cycle = cyclePeriodUs_ * 1e-6;
    const int steps =
        std::max(1, static_cast<int>(std::ceil(cycle / cfg_.max_loop_period_s - 1e-9)));
    if (mech_ && mech_->sharedWithOtherNodes()) {
        prepareLoop(cycle / steps);
        deferredStep_ = 0;
        deferredSteps_ = steps;
        deferredH_ = cycle / steps;
    } else {
        advance(steps, cycle / steps, out);
    }
    lastAdvance_s_ = now_s;
}

void DriveNode::runDeferredStep(std::vector<CanFrame>& out) {
    if (!hasDeferredStep()) return;
    loopStep(deferredStep_++, deferredSteps_, deferredH_, out);
}

void DriveNode::onRpdo(int which, const CanFrame& in, double now_s, std::vector<CanFrame>& out) {
    const Pdo& p = rpdo_[static_cast<size_t>(which)];
    int bytes = 0;
    for (int i = 0; i < p.count; ++i)
        bytes += static_cast<int>((p.map[static_cast<size_t>(i)] & 0xFF) / 8);
    if (in.len < bytes) {
        raiseFault(0x8210, out); // PDO not processed due to length error
        return;
    }
    pendingRpdo_[static_cast<size_t>(which)] = in.data;
    rpdoPending_[static_cast<size_t>(which)] = true;
    if (p.type > 240) applyRpdoData(which, now_s, out); // event-driven: act now
}

void DriveNode::applyRpdoData(int which, double now_s, std::vector<CanFrame>& out) {
    rpdoPending_[static_cast<size_t>(which)] = false;
    const Pdo& p = rpdo_[static_cast<size_t>(which)];
    const auto& d = pendingRpdo_[static_cast<size_t>(which)];
    int byte = 0;
    for (int i = 0; i < p.count; ++i) {
        const std::uint32_t e = p.map[static_cast<size_t>(i)];
        const int size = static_cast<int>((e & 0xFF) / 8);
        std::uint32_t v = 0;
        for (int b = size - 1; b >= 0; --b)
            v = (v << 8) | d[static_cast<size_t>(byte + b)];
        byte += size;
        write({static_cast<std::uint16_t>(e >> 16), static_cast<std::uint8_t>(e >> 8)}, v, size,
              now_s, out);
    }
}

void DriveNode::setControlword(std::uint16_t c, double now_s, std::vector<CanFrame>& out) {
    const std::uint16_t prev = controlword_;
    controlword_ = c;
    const Cia402State next = applyControlword(state_, prev, c);
    if (state_ == Cia402State::Fault && next != Cia402State::Fault) {
        errorCode_ = 0;
        followingError_ = torqueLost_ = false;
        out.push_back(encodeEmcy(cfg_.node, emcy_code::kNone, 0)); // error reset
    }
    if (next != state_) enterState(next, now_s);
}

void DriveNode::enterState(Cia402State s, double now_s) {
    if (state_ == Cia402State::OperationEnabled && s != state_) disabledAtSync_ = syncs_;
    if (s == Cia402State::OperationEnabled) {
        // Hold the actual position: the set-point starts where the axis is (no jump); no
        // torque until the master's first target torque.
        previousTargetRad_ = cycleTargetRad_ = plantPosition();
        targetTorque_ = 0;
        // Taking over from the brake (if the mechanics have one): the loop starts with the
        // torque that holds the axis (0 without one: a reset loop).
        pid_.preload(mech_ ? mech_->holdingTorque() : 0.0);
        enabledSince_s_ = now_s;
    } else {
        enabledSince_s_ = -1;
    }
    if (s == Cia402State::QuickStopActive) {
        previousTargetRad_ = plantPosition();
        quickStopVelocity_ = plantVelocity();
        // CST: the quick stop takes the torque away at once (no position loop to brake with).
        if (mode_ == kModeCyclicSyncTorque) s = Cia402State::SwitchOnDisabled;
    }
    state_ = s;
    updateBrake();
}

void DriveNode::raiseFault(std::uint16_t code, std::vector<CanFrame>& out) {
    if (state_ == Cia402State::OperationEnabled) disabledAtSync_ = syncs_;
    state_ = Cia402State::Fault; // fault reaction: power stage off at once
    updateBrake();
    enabledSince_s_ = -1;
    errorCode_ = code;
    out.push_back(encodeEmcy(cfg_.node, code, errorRegisterFor(code)));
}

void DriveNode::advance(int steps, double h, std::vector<CanFrame>& out) {
    prepareLoop(h);
    for (int j = 0; j < steps; ++j)
        loopStep(j, steps, h, out);
}

void DriveNode::prepareLoop(double h) {
    if (std::fabs(h - loopPeriod_) > 1e-12) {
        loopPeriod_ = h;
        const double q = plant_.position(), v = plant_.velocity(); // the joint model's own
        pid_.configure(cfg_.gains, h);
        plant_.configure(cfg_.plant, h);
        plant_.setState(q, v);
    }
}

void DriveNode::loopStep(int j, int steps, double h, std::vector<CanFrame>& out) {
    const double window = followingWindow_ / cfg_.counts_per_rad;
    const double decel = quickStopDecel_ / cfg_.counts_per_rad;
    double u = 0;
    if (mode_ == kModeCyclicSyncTorque) {
        // CST: the master's torque, only while enabled (no position loop, no window).
        if (state_ == Cia402State::OperationEnabled && !torqueLost_)
            u = targetTorque_ * 1e-3 * ratedTorque();
    } else if (state_ == Cia402State::OperationEnabled) {
        const double r = previousTargetRad_ + (cycleTargetRad_ - previousTargetRad_) * j / steps;
        const double e = r - plantPosition();
        u = pid_.step(e);
        if (torqueLost_) u = 0;
        if (std::fabs(e) > window) {
            followingError_ = true;
            raiseFault(emcy_code::kFollowingError, out);
            u = 0;
        }
    } else if (state_ == Cia402State::QuickStopActive) {
        // Reference decelerates at 0x6085 to rest; the position loop follows it.
        const double dv = std::min(std::fabs(quickStopVelocity_), decel * h);
        quickStopVelocity_ -= std::copysign(dv, quickStopVelocity_);
        previousTargetRad_ += quickStopVelocity_ * h;
        u = pid_.step(previousTargetRad_ - plantPosition());
        if (quickStopVelocity_ == 0 && std::fabs(plantVelocity()) < 1e-3 && quickStopOption_ != 6) {
            enterState(Cia402State::SwitchOnDisabled, -1);
            u = 0;
        }
    }
    lastTorque_ = plantStep(u, h);
}

DriveNode::Pdo* DriveNode::pdoFor(std::uint16_t index) {
    switch (index) {
    case od::kRpdoComm:
    case od::kRpdoMap:
        return &rpdo_[0];
    case od::kRpdoComm + 1:
    case od::kRpdoMap + 1:
        return &rpdo_[1];
    case od::kTpdoComm:
    case od::kTpdoMap:
        return &tpdo_[0];
    default:
        return nullptr;
    }
}

std::uint16_t DriveNode::statusword() const {
    std::uint16_t s = encodeStatusword(state_) | sw::kVoltageEnabled | sw::kRemote;
    if (followingError_) s |= sw::kFollowingError;
    if (state_ == Cia402State::OperationEnabled && mode_ != kModeCyclicSyncTorque &&
        std::fabs(cycleTargetRad_ - plantPosition()) * cfg_.counts_per_rad < 10)
        s |= sw::kTargetReached;
    return s;
}

std::int32_t DriveNode::actualCounts() const {
    return static_cast<std::int32_t>(std::lround(plantPosition() * cfg_.counts_per_rad));
}

} // namespace cutcell::canopen
