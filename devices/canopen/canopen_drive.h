#pragma once
// One CiA 402 drive on the CAN bus as the engine's AxisDrive.
//
// Threading contract: every method is called from the engine thread only and touches nothing
// but the node's atomics (NodeShared) and, for the urgent commands, one write() to the
// master's eventfd - no lock, no allocation, no Qt. The master thread does the CAN I/O.
// Units: rad for rotary axes, mm for linear ones; counts_per_unit converts (per deg or mm).
#include "core/devices/device_interfaces.h"
#include "devices/canopen/node_shared.h"

#include <cstdint>

namespace cutcell::canopen {

class CanOpenMaster;

class CanOpenDrive final : public AxisDrive {
  public:
    // syncFd >= 0: write() also posts one cycle to the master (the last drive of a
    // SyncSource::LastDriveWrite master).
    CanOpenDrive(int node, double countsPerUnit, bool linear, NodeShared& shared, int wakeFd,
                 int syncFd = -1, AxisCommandMode mode = AxisCommandMode::Position);

    void activate() override;
    void deactivate() override;
    void quickStop() override;
    void faultReset() override;
    DriveFeedback read(double now_s) override;
    void write(double targetPosition) override;
    // CST: torque (N m, or N on a linear axis) as per mille of the drive's rated torque 0x6076.
    void writeTorque(double targetTorque) override;
    // The mode is the node's configuration (0x6060 written at start-up): only that one.
    bool setCommandMode(AxisCommandMode mode) override { return mode == mode_; }
    AxisCommandMode commandMode() const override { return mode_; }

    int node() const { return node_; }
    double countsPerAxisUnit() const { return countsPerAxisUnit_; }

  private:
    void command(DriveGoal goal, bool urgent);
    void postSync();

    int node_;
    double countsPerAxisUnit_; // counts per rad (rotary) or per mm (linear)
    NodeShared& shared_;
    int wakeFd_;
    int syncFd_;
    AxisCommandMode mode_;
    std::uint32_t seenEpoch_ = 0; // enable epoch last reported to the engine as Enabled
    std::uint64_t writes_ = 0;    // targets written (one per engine cycle)
    void publish(std::uint64_t taggedTarget);
};

// Fault codes the master raises itself (DriveFeedback::fault_code), beside EMCY codes and SDO
// abort codes (0x05..., 0x06..., 0x08...).
namespace master_fault {
inline constexpr std::uint32_t kHeartbeatLost = 0x8130;
inline constexpr std::uint32_t kBusOff = 0x8140;
inline constexpr std::uint32_t kBusLost = 0x8100;
inline constexpr std::uint32_t kNoBootUp = 0x8101;      // node silent at start-up
inline constexpr std::uint32_t kWrongDevice = 0x8102;   // device type is not a CiA 402 drive
inline constexpr std::uint32_t kRebooted = 0x8103;      // unexpected boot-up while running
inline constexpr std::uint32_t kOtherMaster = 0x8104;   // another master owns the bus
inline constexpr std::uint32_t kNoProcessData = 0x8105; // SYNC unanswered (no TPDO) too long
} // namespace master_fault

} // namespace cutcell::canopen
