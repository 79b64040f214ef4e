#include "core/trajectory/speed_profile.h"

#include "core/common/types.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

SpeedProfile::SpeedProfile(double length_mm, double speed_mm_s, double ramp_s)
    : length_(length_mm), v_(speed_mm_s) {
    // A ramp covers v * ramp / 2; shorten the ramps when the cut is too short for them.
    ramp_ = std::min(ramp_s, length_mm / speed_mm_s);
    duration_ = length_mm / speed_mm_s + ramp_;
}

double SpeedProfile::speed(double t) const {
    if (t <= 0 || t >= duration_) return 0;
    if (t < ramp_) return v_ * (1 - std::cos(kPi * t / ramp_)) / 2;
    if (t > duration_ - ramp_) return speed(duration_ - t);
    return v_;
}

double SpeedProfile::distance(double t) const {
    if (t <= 0) return 0;
    if (t >= duration_) return length_;
    const auto ramp = [&](double u) {
        return v_ / 2 * (u - ramp_ / kPi * std::sin(kPi * u / ramp_));
    };
    if (t < ramp_) return ramp(t);
    if (t > duration_ - ramp_) return length_ - ramp(duration_ - t);
    return v_ * ramp_ / 2 + v_ * (t - ramp_);
}

} // namespace cutcell
