#pragma once
// A simulated line encoder on a measuring roller: the master axis of a flying saw (a pipe line
// the engine does not drive). The line's speed follows a profile v(t) = v0 (1 + A sin(2 pi t /
// P)); the reading is the roller's travel, which misses slip_fraction of the line's travel
// from slip_from_s on (a slipping roller), quantised to whole counts and disturbed by uniform
// noise of +-noise amplitude (deterministic: seeded). Units: mm and mm/s.
//
// Threading contract: read() from the engine thread; inject*() from any thread; the true-line
// probes are pure functions of time (any thread).
#include "core/devices/device_interfaces.h"

#include <atomic>
#include <cstdint>

namespace cutcell {

struct LineEncoderConfig {
    double start_mm = 0;
    double speed_mm_s = 500;
    double speed_amplitude = 0; // A: fraction of v0 (0.1 = +-10 %)
    double speed_period_s = 4;  // P
    double counts_per_mm = 100; // quantisation: 1 / counts_per_mm
    double noise_mm = 0;        // uniform in [-noise, +noise]
    double slip_fraction = 0;
    double slip_from_s = 0;
    std::uint32_t seed = 1;
};

class LineEncoder : public SensorInput {
  public:
    explicit LineEncoder(const LineEncoderConfig& config) : cfg_(config), rng_(config.seed) {}

    SensorReading read(double now_s) override;
    void injectInvalid(bool on) { invalid_.store(on); }

    // The line itself (not the reading).
    double linePosition(double t) const;
    double lineSpeed(double t) const;
    double maxAcceleration() const; // of the line, mm/s^2
    // Largest measurement error of a reading without slip: half a count plus the noise.
    double maxReadingError() const { return 0.5 / cfg_.counts_per_mm + cfg_.noise_mm; }

  private:
    double noise();
    LineEncoderConfig cfg_;
    std::uint32_t rng_;
    std::atomic<bool> invalid_{false};
};

} // namespace cutcell
