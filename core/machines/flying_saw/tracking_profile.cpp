#include "core/machines/flying_saw/tracking_profile.h"

#include "core/common/types.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

double rampTime(double v, const CarriageLimits& lim) {
    v = std::fabs(v);
    const double byAccel = kPi * v / (2 * lim.max_accel_mm_s2);
    const double byJerk = kPi * std::sqrt(v / (2 * lim.max_jerk_mm_s3));
    return std::max(byAccel, byJerk);
}

double ForwardStroke::accel(double u) const {
    const double s = std::clamp(u / d1, 0.0, 1.0);
    return d1 * (s / 2 - std::sin(kPi * s) / (2 * kPi));
}
double ForwardStroke::accelSlope(double u) const {
    const double s = std::clamp(u / d1, 0.0, 1.0);
    const double h = std::sin(kPi * s / 2);
    return h * h;
}
double ForwardStroke::accelCurvature(double u) const {
    const double s = std::clamp(u / d1, 0.0, 1.0);
    return kPi / (2 * d1) * std::sin(kPi * s);
}
double ForwardStroke::decel(double u) const {
    const double s = std::clamp(u / d3, 0.0, 1.0);
    return d3 * (s / 2 + std::sin(kPi * s) / (2 * kPi));
}
double ForwardStroke::decelSlope(double u) const {
    const double s = std::clamp(u / d3, 0.0, 1.0);
    const double h = std::cos(kPi * s / 2);
    return h * h;
}
double ForwardStroke::decelCurvature(double u) const {
    const double s = std::clamp(u / d3, 0.0, 1.0);
    return -kPi / (2 * d3) * std::sin(kPi * s);
}

double ReverseProfile::travel(double t) const {
    if (t <= 0) return 0;
    if (t >= duration()) return distance; // exactly: the carriage ends where it started
    const double rampLen = v * ta / 2;
    if (t < ta) return v * (t / 2 - ta * std::sin(kPi * t / ta) / (2 * kPi));
    if (t < ta + ts) return rampLen + v * (t - ta);
    const double u = t - ta - ts;
    return rampLen + v * ts + v * (u / 2 + ta * std::sin(kPi * u / ta) / (2 * kPi));
}
double ReverseProfile::speed(double t) const {
    if (t <= 0 || t >= duration()) return 0;
    if (t < ta) return v * 0.5 * (1 - std::cos(kPi * t / ta));
    if (t < ta + ts) return v;
    return v * 0.5 * (1 + std::cos(kPi * (t - ta - ts) / ta));
}
double ReverseProfile::accel(double t) const {
    if (t <= 0 || t >= duration()) return 0;
    if (t < ta) return v * kPi / (2 * ta) * std::sin(kPi * t / ta);
    if (t < ta + ts) return 0;
    return -v * kPi / (2 * ta) * std::sin(kPi * (t - ta - ts) / ta);
}

ReverseProfile fastestReverse(double distance, const CarriageLimits& lim) {
    ReverseProfile r;
    r.distance = std::max(distance, 0.0);
    if (r.distance <= 0) return r;
    const double vmax = lim.max_speed_mm_s;
    // Without a synchronous period the travel is v * Ta(v), increasing in v.
    if (vmax * rampTime(vmax, lim) <= r.distance) {
        r.v = vmax;
        r.ta = rampTime(vmax, lim);
        r.ts = r.distance / vmax - r.ta;
        return r;
    }
    double lo = 0, hi = vmax;
    for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (lo + hi);
        (mid * rampTime(mid, lim) < r.distance ? lo : hi) = mid;
    }
    r.ta = rampTime(hi, lim);
    r.v = r.distance / r.ta; // <= hi: within the limits; v Ta = distance exactly, Ts = 0
    r.ts = 0;
    return r;
}

double seedK(double T1, double T2) {
    return std::sqrt(T1 * (T1 + T2)) / T1;
}

double seedReturnMiss(double V, double T1, double T2, double T5) {
    const double forward = V * T1 / 2 + V * T2 + V * T1 / 2;
    const double k = seedK(T1, T2);
    const double back = k * V * T1 / 2 + k * V * T5 + k * V * T1 / 2;
    return forward - back;
}

} // namespace cutcell
