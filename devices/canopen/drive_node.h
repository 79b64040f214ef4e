#pragma once
// One simulated CiA 402 servo drive as a CANopen slave, without any transport: frames in,
// frames out. Object-dictionary subset, expedited SDO server, NMT slave, heartbeat producer,
// EMCY producer, PDOs by their configured mapping, the CiA 402 state machine in CSP mode, and
// the same PID + joint plant as the in-process simulation, run at an internal loop period
// (<= 1 ms) with the target interpolated linearly between SYNCs, as real CSP drives do.
//
// Timing of a SYNC: the TPDOs sample the state at the SYNC instant; then the RPDO data
// received before the SYNC takes effect and the drive moves toward that target over the next
// communication cycle (0x1006). A target sent before SYNC k is thus reached at SYNC k+1.
// Out of Operation Enabled and without SYNCs (none for 3 cycles) the loop runs on by the wall
// clock, so a quick stop or a coasting axis comes to rest when the master has gone quiet. In
// Operation Enabled a SYNC gap of max(100 ms, 20 cycles) is a fault (0x8250, RPDO timeout): a
// drive never keeps following a master that has gone silent.
// Heartbeat consumer (0x1016:01 = producer node << 16 | time ms): from the first heartbeat of
// that node on, a gap longer than the time sends EMCY 0x8130 and reacts as 0x6007 (abort
// connection option code) says: 0 nothing, 1 Fault, 2 disable voltage, 3 quick stop; an
// Operational node then enters Pre-operational (CiA 301 error behaviour default).
//
// Cyclic synchronous torque mode (0x6060 = 10, CST): RPDO1 carries the target torque 0x6071
// (per mille of the rated torque 0x6076), applied over the next cycle from the SYNC on. Torque
// flows only in Operation Enabled: a quick stop or a disable takes it away at once (no torque
// ramp; the mechanism coasts), so an emergency stop removes it within the cycle it arrives in.
//
// Threading: not thread-safe; DriveSimulator drives it from its own thread.
#include "core/control/joint_plant.h"
#include "core/control/pid_filter.h"
#include "devices/canopen/can_frame.h"
#include "devices/canopen/cia402.h"
#include "devices/canopen/nmt.h"
#include "devices/canopen/sdo.h"
#include "devices/canopen/torque_plant.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace cutcell::canopen {

// Faults a test or a demo can inject (times in s; < 0 = never).
struct FaultInjection {
    std::uint16_t fault_code = 0;       // raise this EMCY code ...
    double fault_after_s = -1;          // ... after this long in Operation Enabled
    double heartbeat_stop_after_s = -1; // stop producing heartbeats after this long Operational
    double torque_loss_after_s = -1;    // the motor loses its torque after this long in
                                        // Operation Enabled: the following error grows
    std::uint16_t refuse_sdo_index = 0; // SDO writes to this object get abort 0x06090030
                                        // (invalid value): a bring-up that cannot complete
};

struct DriveNodeConfig {
    int node = 1;
    PidGains gains;
    JointPlantParams plant;
    double counts_per_rad = 1000 * 180 / 3.14159265358979323846;
    double max_loop_period_s = 0.001;                // internal position loop
    std::uint32_t following_error_window_counts = 0; // 0: 5 deg worth of counts
    double quick_stop_decel_rad_s2 = 20;             // 0x6085 default, converted to counts/s^2
    double start_position_rad = 0;
    FaultInjection faults;
    // Mechanics other than the joint model above (its gains and plant then unused in CST);
    // null: JointPlant(plant). The node drives it; its rated torque is 0x6076.
    std::shared_ptr<TorquePlant> mechanics;
};

class DriveNode {
  public:
    explicit DriveNode(const DriveNodeConfig& c);

    // Boot: emits the boot-up message and enters Pre-operational.
    void boot(double now_s, std::vector<CanFrame>& out);
    void handle(const CanFrame& in, double now_s, std::vector<CanFrame>& out);
    // Periodic work without a frame: heartbeat production, injected faults.
    void tick(double now_s, std::vector<CanFrame>& out);

    // Fault injection now (tests, demos): EMCY + Fault with this code; heartbeats stop.
    void injectFault(std::uint16_t code, std::vector<CanFrame>& out) { raiseFault(code, out); }
    void stopHeartbeat() { heartbeatStopped_ = true; }

    // Coupled mechanics (TorquePlant::sharedWithOtherNodes): a SYNC leaves the loop steps of
    // the coming cycle to be run one at a time, interleaved with the other nodes' (the drive
    // simulator runs them right after the SYNC has reached every node).
    bool hasDeferredStep() const { return deferredStep_ < deferredSteps_; }
    void runDeferredStep(std::vector<CanFrame>& out);

    int node() const { return cfg_.node; }
    NmtState nmtState() const { return nmt_; }
    Cia402State driveState() const { return state_; }
    double positionRad() const { return plantPosition(); }
    double appliedTorque() const { return lastTorque_; }
    // The SYNC count when the power stage last left Operation Enabled (0: never).
    std::uint64_t disabledAtSync() const { return disabledAtSync_; }
    std::int8_t mode() const { return mode_; }
    std::uint16_t errorCode() const { return errorCode_; }
    std::uint64_t syncCount() const { return syncs_; }

  private:
    struct Pdo {
        std::uint32_t cob_id = kInvalid;
        std::uint8_t type = 1;
        std::uint8_t count = 0;
        std::array<std::uint32_t, 8> map{};
        bool valid() const { return !(cob_id & kInvalid); }
        static constexpr std::uint32_t kInvalid = 0x80000000u;
    };

    void resetCommunication();
    void onNmt(NmtCommand c, double now_s, std::vector<CanFrame>& out);
    void onSdo(const CanFrame& in, std::vector<CanFrame>& out);
    void onSync(double now_s, std::vector<CanFrame>& out);
    void onRpdo(int which, const CanFrame& in, double now_s, std::vector<CanFrame>& out);
    void applyRpdoData(int which, double now_s, std::vector<CanFrame>& out);
    void setControlword(std::uint16_t cw, double now_s, std::vector<CanFrame>& out);
    void enterState(Cia402State s, double now_s);
    void raiseFault(std::uint16_t code, std::vector<CanFrame>& out);
    // The mechanics' brake follows the power stage (torque only in Operation Enabled and Quick
    // Stop Active).
    void updateBrake();
    void advance(int steps, double h, std::vector<CanFrame>& out);
    // advance() in parts: the loop period for h, then loop step j of `steps`.
    void prepareLoop(double h);
    void loopStep(int j, int steps, double h, std::vector<CanFrame>& out);
    void superviseMaster(double now_s, std::vector<CanFrame>& out);
    // A SYNC's counter against 0x1019 (false: a communication error, already reacted to).
    bool syncInSequence(const CanFrame& in, std::uint8_t counter, double now_s,
                        std::vector<CanFrame>& out);
    // The master's connection is gone or broken (heartbeat, SYNC): EMCY `code`, the 0x6007
    // reaction, and out of Operational.
    void abortConnection(std::uint16_t code, double now_s, std::vector<CanFrame>& out);

    // Object dictionary access; returns 0 or an SDO abort code.
    std::uint32_t read(SdoAddress a, std::uint32_t& value, int& size) const;
    std::uint32_t write(SdoAddress a, std::uint32_t value, int size, double now_s,
                        std::vector<CanFrame>& out);
    Pdo* pdoFor(std::uint16_t index);
    std::uint16_t statusword() const;
    std::int32_t actualCounts() const;
    double plantPosition() const { return mech_ ? mech_->position() : plant_.position(); }
    double plantVelocity() const { return mech_ ? mech_->velocity() : plant_.velocity(); }
    double plantStep(double u, double h) { return mech_ ? mech_->step(u, h) : plant_.step(u); }
    double ratedTorque() const { return mech_ ? mech_->ratedTorque() : cfg_.plant.torque_limit_nm; }

    DriveNodeConfig cfg_;
    PidFilter pid_;
    JointPlant plant_;
    std::shared_ptr<TorquePlant> mech_;
    std::int8_t mode_ = kModeCyclicSyncPosition;
    std::int16_t targetTorque_ = 0; // 0x6071, per mille of 0x6076
    std::uint64_t disabledAtSync_ = 0;
    double loopPeriod_ = 0;
    NmtState nmt_ = NmtState::BootUp;
    Cia402State state_ = Cia402State::SwitchOnDisabled;
    std::uint16_t controlword_ = 0;
    std::uint16_t errorCode_ = 0;
    std::int32_t targetCounts_ = 0; // 0x607A as last written
    double cycleTargetRad_ = 0;     // target reached at the end of the running cycle
    double previousTargetRad_ = 0;  // target at the start of the running cycle
    double quickStopVelocity_ = 0;  // rad/s of the quick-stop ramp
    bool followingError_ = false;
    double lastTorque_ = 0; // N m applied over the last loop step
    bool torqueLost_ = false;
    std::uint32_t cyclePeriodUs_ = 0;
    std::uint8_t syncOverflow_ = 0;    // 0x1019: 0 = SYNC without counter
    std::uint8_t lastSyncCounter_ = 0; // 0: none since the node started
    std::uint16_t heartbeatMs_ = 0;
    std::int16_t quickStopOption_ = 2;
    std::int16_t abortConnectionOption_ = 1; // 0x6007 (CiA 402 default: Fault)
    std::uint32_t consumerHeartbeat_ = 0;    // 0x1016:01; 0 = not watching
    double consumerLastSeen_s_ = -1;         // < 0: not armed (no heartbeat seen yet)
    bool consumerLost_ = false;
    std::uint32_t followingWindow_ = 0;
    std::uint32_t quickStopDecel_ = 0;
    std::array<Pdo, 2> rpdo_{};
    std::array<Pdo, 1> tpdo_{};
    std::array<std::array<std::uint8_t, 8>, 2> pendingRpdo_{}; // synchronous RPDO data
    std::array<bool, 2> rpdoPending_{};
    double nextHeartbeat_s_ = 0;
    double operationalSince_s_ = -1;
    double enabledSince_s_ = -1;
    bool heartbeatStopped_ = false;
    double lastSync_s_ = -1;    // wall time of the last SYNC (< 0: none yet)
    double lastAdvance_s_ = -1; // wall time the plant was last advanced to
    std::uint64_t syncs_ = 0;
    int deferredStep_ = 0, deferredSteps_ = 0; // loop steps of this cycle left to the simulator
    double deferredH_ = 0;
};

// Counts per radian for a joint given in counts per degree (or per mm for linear axes, where
// the plant runs in mm and the factor is used as is).
double countsPerRad(double countsPerUnit, bool linear);

} // namespace cutcell::canopen
