#pragma once
// A stepper-motor axis driven open loop by a pulse card (seed 002: PCL-839+, pulse + direction,
// 1 Hz .. 200 kHz per axis). Each write() the card sends the pulses toward
// round(target / units_per_pulse), at most max_pulse_rate_hz * period_s of them (the card's
// limit: a faster set-point lags and shows as following error). There is no encoder: the
// position read back is the pulse count times units_per_pulse, as on the real machine.
//
// Lifecycle like SimulatedDrive: activate() -> Enabling for enable_delay_s -> Enabled;
// deactivate() -> Disabled (no pulses; the count is kept, an unpowered stepper does not
// coast); quickStop() -> QuickStop (no more pulses) for quick_stop_s, then Disabled.
//
// Threading contract: AxisDrive calls come from the engine thread only; the counters may be
// read by the owner after the engine has stopped (or from the engine thread).
#include "core/devices/device_interfaces.h"

#include <cstdint>

namespace cutcell {

struct SimulatedStepperConfig {
    double units_per_pulse = 0.005; // mm (linear) or rad (rotary) per pulse
    double max_pulse_rate_hz = 200000;
    double period_s = 0.001;
    double initial_position = 0;
    double enable_delay_s = 0.002;
    double quick_stop_s = 0.01;
};

class SimulatedStepper : public AxisDrive {
  public:
    explicit SimulatedStepper(const SimulatedStepperConfig& config);

    void activate() override;
    void deactivate() override;
    void quickStop() override;
    void faultReset() override;
    DriveFeedback read(double now_s) override;
    void write(double targetPosition) override;

    std::int64_t pulsePosition() const { return count_; }
    std::uint64_t pulsesSent() const { return sent_; }           // all pulses, both directions
    std::uint64_t rateLimitedCycles() const { return limited_; } // cycles the card was at its limit

  private:
    SimulatedStepperConfig cfg_;
    std::int64_t maxPerCycle_;
    std::int64_t count_ = 0;
    std::int64_t lastStep_ = 0;
    std::uint64_t sent_ = 0, limited_ = 0;
    DriveState state_ = DriveState::Disabled;
    double stateSince_ = -1;
};

} // namespace cutcell
