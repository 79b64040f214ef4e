#pragma once
// The simulated pipe line and its measuring roller (the flying saw's master, a SensorInput):
//   v(t) = v0 (1 + A sin(2 pi f t) + s(t)),
// s(t) steps between -step, 0 and +step at pseudo-random times (mean interval step_interval_s,
// seeded) with a cosine ramp of step_ramp_s (a mill's speed changes take time). The roller
// reads the line's travel short by slip_fraction, quantised to whole pulses of the encoder's
// resolution, plus uniform noise. The true line position is integrated per read() (Simpson on
// a C1 speed: exact to rounding at 1 ms), so read() times must not go backwards.
//
// Threading: read() and the probes from one thread (the engine's, or a simulation loop). The
// step times are drawn at construction (allocation outside the cycle).
#include "core/devices/device_interfaces.h"
#include "core/machines/flying_saw/flying_saw_spec.h"

#include <cstdint>
#include <vector>

namespace cutcell {

struct PipeLineConfig {
    double speed_mm_s = 1000;
    double resolution_mm = 0.05;
    double duration_s = 3600; // steps drawn up to here
    LineSimSpec sim;
};

class PipeLineSim : public SensorInput {
  public:
    explicit PipeLineSim(const PipeLineConfig& c);
    SensorReading read(double now_s) override;

    double speed(double t) const;
    // The line's true travel at the time of the last read() (advance() moves it on).
    double position() const { return x_; }
    double time() const { return t_; }
    void advance(double t);
    double stepLevel(double t) const; // s(t)
    int stepCount() const { return static_cast<int>(steps_.size()); }

  private:
    PipeLineConfig c_;
    struct Step {
        double t, from, to;
    };
    std::vector<Step> steps_;
    double t_ = 0, x_ = 0;
    std::uint32_t rng_;
};

} // namespace cutcell
