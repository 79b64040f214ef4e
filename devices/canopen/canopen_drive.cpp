#include "devices/canopen/canopen_drive.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <unistd.h>

namespace cutcell::canopen {

CanOpenDrive::CanOpenDrive(int node, double countsPerUnit, bool linear, NodeShared& shared,
                           int wakeFd, int syncFd, AxisCommandMode mode)
    : node_(node),
      countsPerAxisUnit_(linear ? countsPerUnit : countsPerUnit * 180.0 / std::numbers::pi),
      shared_(shared), wakeFd_(wakeFd), syncFd_(syncFd), mode_(mode) {}

void CanOpenDrive::command(DriveGoal goal, bool urgent) {
    shared_.goal.store(static_cast<std::uint8_t>(goal), std::memory_order_release);
    if (urgent) shared_.urgent.store(true, std::memory_order_release);
    postEventFd(wakeFd_);
}

void CanOpenDrive::activate() {
    command(DriveGoal::OperationEnabled, false);
}
void CanOpenDrive::deactivate() {
    command(DriveGoal::Disabled, true);
}
void CanOpenDrive::quickStop() {
    command(DriveGoal::QuickStop, true);
}

void CanOpenDrive::faultReset() {
    shared_.fault_reset_requests.fetch_add(1, std::memory_order_acq_rel);
    command(DriveGoal::Disabled, false);
}

DriveFeedback CanOpenDrive::read(double) {
    DriveFeedback fb;
    const std::uint16_t sw = shared_.statusword.load(std::memory_order_acquire);
    const Cia402State s = decodeStatusword(sw);
    const std::uint32_t masterFault = shared_.master_fault.load(std::memory_order_acquire);
    const auto goal = static_cast<DriveGoal>(shared_.goal.load(std::memory_order_acquire));
    const bool configured = shared_.configured.load(std::memory_order_acquire);
    fb.position = shared_.actual_counts.load(std::memory_order_acquire) / countsPerAxisUnit_;
    // Loaded after the position: as new as the position's tag or newer (the age reads low).
    const std::uint64_t answered = shared_.tpdo_seq.load(std::memory_order_relaxed);
    // On time: the TPDO answered the SYNC sent after the last write (answered == writes_).
    fb.age_cycles = static_cast<std::uint8_t>(
        answered > 0 && writes_ > answered ? std::min<std::uint64_t>(writes_ - answered, 255) : 0);
    fb.velocity = shared_.velocity_counts_s.load(std::memory_order_acquire) / countsPerAxisUnit_;
    fb.torque_ratio = shared_.torque_permille.load(std::memory_order_relaxed) / 1000.0;
    if (masterFault != 0 || s == Cia402State::Fault || s == Cia402State::FaultReactionActive) {
        fb.state = DriveState::Fault;
        fb.fault_code =
            masterFault != 0 ? masterFault : shared_.last_emcy.load(std::memory_order_acquire);
    } else if (!configured) {
        fb.state =
            goal == DriveGoal::OperationEnabled ? DriveState::Enabling : DriveState::Disabled;
    } else if (s == Cia402State::OperationEnabled) {
        // Whatever was asked, the drive has torque until its statusword says otherwise.
        fb.state = DriveState::Enabled;
        seenEpoch_ = shared_.enable_epoch.load(std::memory_order_acquire);
    } else if (s == Cia402State::QuickStopActive) {
        fb.state = DriveState::QuickStop;
    } else {
        fb.state =
            goal == DriveGoal::OperationEnabled ? DriveState::Enabling : DriveState::Disabled;
    }
    // Stale when the process data stopped (3 cycles' worth is judged by the master, which
    // clears configured on a lost bus; here: no TPDO for 100 ms).
    const std::int64_t now = std::chrono::steady_clock::now().time_since_epoch().count();
    fb.feedback_valid =
        configured && now - shared_.tpdo_ns.load(std::memory_order_acquire) < 100'000'000;
    return fb;
}

void CanOpenDrive::write(double targetPosition) {
    const double counts =
        std::clamp(std::round(targetPosition * countsPerAxisUnit_), -2147483648.0, 2147483647.0);
    publish(NodeShared::tag(seenEpoch_, static_cast<std::int32_t>(counts)));
}

void CanOpenDrive::writeTorque(double targetTorque) {
    const double rated = shared_.rated_torque.load(std::memory_order_acquire);
    // Per mille of the rated torque, within the int16 of 0x6071; nothing before 0x6076 is known.
    const double permille =
        rated > 0 && std::isfinite(targetTorque)
            ? std::clamp(std::round(targetTorque / rated * 1000), -32768.0, 32767.0)
            : 0.0;
    publish(NodeShared::tag(seenEpoch_, static_cast<std::int32_t>(permille)));
}

// This cycle's target: in the ring under its sequence number, then the number (release: the
// master reads the number, then the target), then as the newest; then the SYNC.
void CanOpenDrive::publish(std::uint64_t tagged) {
    ++writes_;
    shared_.targets[writes_ % NodeShared::kTargetRing].store(tagged, std::memory_order_relaxed);
    shared_.write_seq.store(writes_, std::memory_order_release);
    shared_.tagged_target.store(tagged, std::memory_order_release);
    postSync();
}

void CanOpenDrive::postSync() {
    if (syncFd_ >= 0) postEventFd(syncFd_);
}

} // namespace cutcell::canopen
