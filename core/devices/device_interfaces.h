#pragma once
// What the motion engine needs from the hardware. devices/ implements these (simulated drives,
// CANopen CiA 402 drives); app/ chooses which. No transport appears here.
//
// Threading contract: every method is called from the engine thread only. Lifecycle calls are
// requests and return at once; their progress shows in the state read back each cycle.
// read()/write() are called once per cycle and must not block, lock or allocate; read() may
// also be called right after an emergency-stop push (it returns the latest known state).
// Units: rotary axes in rad, rad/s; linear axes in mm, mm/s.
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
};

class AxisDrive {
  public:
    virtual ~AxisDrive() = default;
    virtual void activate() = 0;   // -> Enabled (the drive holds its actual position)
    virtual void deactivate() = 0; // -> Disabled
    virtual void quickStop() = 0;  // -> QuickStop then Disabled
    virtual void faultReset() = 0; // Fault -> Disabled (rising edge on a real drive)
    // Per cycle: now_s is the engine's clock (simulated or real time).
    virtual DriveFeedback read(double now_s) = 0;
    virtual void write(double targetPosition) = 0;
};

struct TorchFeedback {
    bool on = false;
    bool arc_ok = false; // arc established (false while on = arc lost)
    std::uint32_t fault_code = 0;
};

class Torch {
  public:
    virtual ~Torch() = default;
    virtual void setOn(bool on) = 0; // must take effect at once (emergency stop)
    virtual TorchFeedback read(double now_s) = 0;
};

} // namespace cutcell
