#include "core/machines/flying_saw/saw_cycle.h"

#include "core/common/c_format.h"
#include "core/common/types.h"

#include <algorithm>
#include <cmath>

namespace cutcell {
namespace {

double smooth5(double u) {
    u = std::clamp(u, 0.0, 1.0);
    return u * u * u * (10 - 15 * u + 6 * u * u);
}
// Quintic rest-to-rest move over distance d at peak speed v: 1.875 d / v.
double quinticTime(double d, double v) {
    return std::fabs(d) > 0 ? 1.875 * std::fabs(d) / v : 0;
}

} // namespace

CamTable feedCamTable(const TubeOutline& outer, const TubeOutline& cut, double retractRadius,
                      int points) {
    CamTable t;
    t.count = points + 1;
    t.period = kPi;
    const double psiA = outer.cornerA();
    for (int i = 0; i <= points; ++i) {
        const double theta = kPi * i / points;
        t.slave[static_cast<size_t>(i)] = retractRadius - cut.polarRadius(psiA - theta);
    }
    // Central symmetry: the last point is the first (exactly, for the periodic table).
    t.slave[static_cast<size_t>(points)] = t.slave[0];
    return t;
}

std::string buildSawCycle(const TubeOutline& outer, double wall_mm, const SawSettings& s,
                          SawCycle* out) {
    SawCycle c;
    c.outer = outer;
    c.cut = outer.inset(wall_mm + s.overcut_mm);
    if (!(c.cut.half_width > 0 && c.cut.half_height > 0))
        return messageC("the wall + overcut (%.6g mm) leaves no bore in a tube of %.6g x %.6g mm",
                        wall_mm + s.overcut_mm, 2 * outer.half_width, 2 * outer.half_height);
    if (s.table_points + 1 > CamTable::kCapacity || s.table_points < 8)
        return messageC("saw.table_points = %d is outside [8, %d]", s.table_points,
                        CamTable::kCapacity - 1);
    c.retract_radius = outer.maxRadius() + s.clearance_mm;
    c.cam = feedCamTable(outer, c.cut, c.retract_radius, s.table_points);
    const double psiA = outer.cornerA();
    c.feed_fast_end = std::max(0.0, c.retract_radius - outer.polarRadius(psiA) - s.approach_gap_mm);
    c.feed_start = c.cam.slave[0];
    c.t_settle = s.settle_s;
    c.t_fast = quinticTime(c.feed_fast_end, s.fast_feed_mm_s);
    c.t_slow = quinticTime(c.feed_start - c.feed_fast_end, s.slow_feed_mm_s);
    c.t_retract = quinticTime(c.feed_start, s.retract_mm_s);
    CarriageLimits turnLimits;
    turnLimits.max_speed_mm_s = deg2rad(s.turntable_deg_s);
    turnLimits.max_accel_mm_s2 = deg2rad(s.turntable_deg_s2);
    turnLimits.max_jerk_mm_s3 = 1e12;
    c.turn = fastestReverse(kPi, turnLimits);
    *out = c;
    return {};
}

void SawCycle::at(double tau, double* theta, double* feed) const {
    double t = tau - t_settle;
    *theta = 0;
    *feed = 0;
    if (t <= 0) return;
    if (t < t_fast) {
        *feed = feed_fast_end * smooth5(t / t_fast);
        return;
    }
    t -= t_fast;
    if (t < t_slow) {
        *feed = feed_fast_end + (feed_start - feed_fast_end) * smooth5(t / t_slow);
        return;
    }
    t -= t_slow;
    if (t < turn.duration()) {
        *theta = turn.travel(t);
        *feed = cam.at(*theta);
        return;
    }
    t -= turn.duration();
    *theta = kPi;
    *feed = t < t_retract ? feed_start * (1 - smooth5(t / t_retract)) : 0;
}

bool SawCycle::cutting(double tau) const {
    const double from = t_settle + t_fast;
    return tau >= from && tau < turnEnd();
}

} // namespace cutcell
