#include "devices/sim/line_encoder.h"

#include <cmath>
#include <numbers>

namespace cutcell {

double LineEncoder::linePosition(double t) const {
    const double w = 2 * std::numbers::pi / cfg_.speed_period_s;
    // Integral of v0 (1 + A sin(w t)).
    return cfg_.start_mm + cfg_.speed_mm_s * (t + cfg_.speed_amplitude * (1 - std::cos(w * t)) / w);
}

double LineEncoder::lineSpeed(double t) const {
    const double w = 2 * std::numbers::pi / cfg_.speed_period_s;
    return cfg_.speed_mm_s * (1 + cfg_.speed_amplitude * std::sin(w * t));
}

double LineEncoder::maxAcceleration() const {
    return cfg_.speed_mm_s * cfg_.speed_amplitude * 2 * std::numbers::pi / cfg_.speed_period_s;
}

double LineEncoder::noise() {
    if (cfg_.noise_mm <= 0) return 0;
    rng_ = rng_ * 1664525u + 1013904223u; // LCG: deterministic and allocation-free
    const double u = static_cast<double>(rng_ >> 8) / static_cast<double>(1u << 24); // [0, 1)
    return cfg_.noise_mm * (2 * u - 1);
}

SensorReading LineEncoder::read(double now_s) {
    double travel = linePosition(now_s) - cfg_.start_mm;
    double speed = lineSpeed(now_s);
    if (cfg_.slip_fraction > 0 && now_s > cfg_.slip_from_s) {
        const double slipped = linePosition(now_s) - linePosition(cfg_.slip_from_s);
        travel -= cfg_.slip_fraction * slipped;
        speed *= 1 - cfg_.slip_fraction;
    }
    SensorReading r;
    r.position = cfg_.start_mm +
                 std::floor(travel * cfg_.counts_per_mm + 0.5) / cfg_.counts_per_mm + noise();
    r.velocity = speed;
    r.valid = !invalid_.load(std::memory_order_relaxed);
    return r;
}

} // namespace cutcell
