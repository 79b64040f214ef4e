#include "core/machines/flying_saw/pipe_line_sim.h"

#include "core/common/types.h"

#include <algorithm>
#include <cmath>

namespace cutcell {
namespace {
std::uint32_t lcg(std::uint32_t& s) {
    s = s * 1664525u + 1013904223u;
    return s;
}
double unit(std::uint32_t& s) { // [0, 1)
    return static_cast<double>(lcg(s) >> 8) / static_cast<double>(1u << 24);
}
} // namespace

PipeLineSim::PipeLineSim(const PipeLineConfig& c) : c_(c), rng_(c.sim.seed * 2654435761u + 1) {
    std::uint32_t s = c.sim.seed + 12345u;
    if (c.sim.step_fraction > 0 && c.sim.step_interval_s > 0) {
        double t = 0, level = 0;
        const double levels[3] = {-c.sim.step_fraction, 0.0, c.sim.step_fraction};
        while (true) {
            t += c.sim.step_interval_s * (0.5 + unit(s));
            if (t > c.duration_s) break;
            double to = level;
            while (to == level)
                to = levels[lcg(s) % 3];
            steps_.push_back({t, level, to});
            level = to;
        }
    }
}

double PipeLineSim::stepLevel(double t) const {
    // Steps are sorted; the last one begun decides (ramps do not overlap: interval >> ramp).
    auto it = std::upper_bound(steps_.begin(), steps_.end(), t,
                               [](double x, const Step& st) { return x < st.t; });
    if (it == steps_.begin()) return 0;
    const Step& st = *(it - 1);
    const double ramp = c_.sim.step_ramp_s;
    if (ramp <= 0 || t >= st.t + ramp) return st.to;
    const double u = (t - st.t) / ramp;
    return st.from + (st.to - st.from) * 0.5 * (1 - std::cos(kPi * u));
}

double PipeLineSim::speed(double t) const {
    return c_.speed_mm_s *
           (1 + c_.sim.wander_fraction * std::sin(2 * kPi * c_.sim.wander_hz * t) + stepLevel(t));
}

void PipeLineSim::advance(double t) {
    if (t <= t_) return;
    const double h = t - t_;
    x_ += h / 6 * (speed(t_) + 4 * speed(t_ + h / 2) + speed(t));
    t_ = t;
}

SensorReading PipeLineSim::read(double now_s) {
    advance(now_s);
    const double roller = x_ * (1 - c_.sim.slip_fraction);
    double noise = 0;
    if (c_.sim.noise_mm > 0) noise = c_.sim.noise_mm * (2 * unit(rng_) - 1);
    SensorReading r;
    r.position = std::floor(roller / c_.resolution_mm + 0.5) * c_.resolution_mm + noise;
    r.velocity = speed(now_s) * (1 - c_.sim.slip_fraction);
    r.valid = true;
    return r;
}

} // namespace cutcell
