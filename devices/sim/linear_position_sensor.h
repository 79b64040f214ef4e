#pragma once
// A simulated linear position sensor (a slider's scale): reads the true position of a
// simulated axis, times a gain plus an offset (a linkage), rounded to the sensor's resolution.
// Fault injection: the reading goes invalid (cable, scale dirt).
//
// Threading contract: read() from the engine thread; injectInvalid() from any thread.
#include "core/devices/device_interfaces.h"

#include <atomic>
#include <cmath>

namespace cutcell {

// What the sensor looks at (a simulated axis's true state).
class TruePositionProbe {
  public:
    virtual ~TruePositionProbe() = default;
    virtual double truePosition() const = 0;
    virtual double trueVelocity() const = 0;
};

class LinearPositionSensor : public SensorInput {
  public:
    LinearPositionSensor(const TruePositionProbe& probe, double resolution_mm, double gain = 1,
                         double offset_mm = 0)
        : probe_(probe), resolution_(resolution_mm), gain_(gain), offset_(offset_mm) {}

    SensorReading read(double now_s) override {
        (void)now_s;
        const double x = gain_ * probe_.truePosition() + offset_;
        SensorReading r;
        r.position = resolution_ > 0 ? std::round(x / resolution_) * resolution_ : x;
        r.velocity = gain_ * probe_.trueVelocity();
        r.valid = !invalid_.load(std::memory_order_relaxed);
        return r;
    }
    void injectInvalid(bool on) { invalid_.store(on); }
    double resolution() const { return resolution_; }

  private:
    const TruePositionProbe& probe_;
    double resolution_, gain_, offset_;
    std::atomic<bool> invalid_{false};
};

} // namespace cutcell
