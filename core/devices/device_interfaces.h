#pragma once
// What the motion engine needs from the hardware. devices/ implements these (simulated drives,
// CANopen CiA 402 drives); app/ chooses which. No transport appears here.
//
// Threading contract: every method is called from the engine thread only. Lifecycle calls are
// requests and return at once; their progress shows in the state read back each cycle.
// read()/write() are called once per cycle and must not block, lock or allocate; read() may
// also be called right after an emergency-stop push (it returns the latest known state).
// Units: rotary axes in rad, rad/s, N m; linear axes in mm, mm/s, N.
#include <cstdint>

namespace cutcell {

// A CiA 402-like view of a drive's power state.
enum class DriveState : std::uint8_t {
    Disabled,  // no torque (switch on disabled / ready to switch on)
    Enabling,  // transition requested, not yet in operation
    Enabled,   // operation enabled: following the target position
    QuickStop, // quick stop active (decelerating or stopped), torque on
    Fault,     // fault latched; faultReset() needed
};
const char* toString(DriveState s);

struct DriveFeedback {
    double position = 0;
    double velocity = 0;
    DriveState state = DriveState::Disabled;
    std::uint32_t fault_code = 0; // CiA 402 / EMCY error code, 0 = none
    bool feedback_valid = true;   // false when the drive's data is stale (bus loss, frozen encoder)
    double torque_ratio = 0; // torque applied over the last period / rated torque (CiA 402 0x6077)
    // How many cycles older than usual `position` is: 0 for a drive read in process and for a
    // TPDO that answered the last SYNC; n when the bus brought the answer n cycles late (the
    // engine then compares it with the set-point of n cycles ago, not with today's).
    std::uint8_t age_cycles = 0;
};

// How an axis is commanded: CiA 402 cyclic synchronous position / velocity / torque.
enum class AxisCommandMode : std::uint8_t {
    Position, // CSP: target position every cycle; the drive closes the loops
    Velocity, // CSV: target velocity every cycle
    Torque,   // CST: target torque (force) every cycle; the loop is closed by the engine
};
const char* toString(AxisCommandMode m);

class AxisDrive {
  public:
    virtual ~AxisDrive() = default;
    virtual void activate() = 0;   // -> Enabled (the drive holds its actual position)
    virtual void deactivate() = 0; // -> Disabled
    virtual void quickStop() = 0;  // -> QuickStop then Disabled
    virtual void faultReset() = 0; // Fault -> Disabled (rising edge on a real drive)
    // Per cycle: now_s is the engine's clock (simulated or real time).
    virtual DriveFeedback read(double now_s) = 0;
    // Per cycle, the command of the drive's mode (exactly one of the three is called).
    virtual void write(double targetPosition) = 0;                              // CSP
    virtual void writeVelocity(double targetVelocity) { (void)targetVelocity; } // CSV
    virtual void writeTorque(double targetTorque) { (void)targetTorque; }       // CST
    // The command mode is chosen before the run, outside the cycle (a CANopen drive writes
    // 0x6060 by SDO), while the drive is disabled; false if the drive does not offer it. The
    // engine refuses a program whose axis modes differ from its drives'.
    virtual bool setCommandMode(AxisCommandMode mode) { return mode == AxisCommandMode::Position; }
    virtual AxisCommandMode commandMode() const { return AxisCommandMode::Position; }
};

// An external encoder or sensor (a line encoder on a measuring roller, a slider's scale):
// read once per cycle, never blocks. Units as the axes.
struct SensorReading {
    double position = 0;
    double velocity = 0;
    bool valid = false; // false: no fresh, trustworthy value (cable, bus loss, scale error)
    std::uint32_t fault_code = 0;
    std::uint8_t age_cycles = 0; // cycles older than usual (a late TPDO), as DriveFeedback's
};

class SensorInput {
  public:
    virtual ~SensorInput() = default;
    virtual SensorReading read(double now_s) = 0;
};

// A process tool: a cutting torch or a saw. On/off and "process OK" (arc established, blade
// at speed); false while on means the process was lost (arc out, blade stalled).
struct ProcessToolFeedback {
    bool on = false;
    bool process_ok = false;
    std::uint32_t fault_code = 0;
};

class ProcessTool {
  public:
    virtual ~ProcessTool() = default;
    virtual void setOn(bool on) = 0; // must take effect at once (emergency stop)
    virtual ProcessToolFeedback read(double now_s) = 0;
};

// The torch is the process tool of the cutting machines.
using Torch = ProcessTool;
using TorchFeedback = ProcessToolFeedback;

} // namespace cutcell
