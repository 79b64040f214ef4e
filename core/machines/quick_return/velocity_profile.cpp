#include "core/machines/quick_return/velocity_profile.h"

#include <cmath>

namespace cutcell::quick_return {

VelocityProfile algorithm1(double y_start, double y_end, double l_c, double l_d, double v) {
    VelocityProfile p;
    p.y_start = y_start;
    p.y_end = y_end;
    p.v = v;
    p.l_c = l_c;
    p.l_d = l_d;
    if (!(std::fabs(v) > 0) || !std::isfinite(v)) {
        p.problem = "the cutting velocity must be a finite number other than 0";
        return p;
    }
    if (!(l_d > 0 && l_d < l_c)) {
        p.problem = "the workpiece length L_d must be > 0 and shorter than the stroke L_c";
        return p;
    }
    if ((y_end - y_start) * v <= 0) {
        p.problem = "the cutting velocity's sign must point from the stroke start to its end";
        return p;
    }
    p.t_c = l_d / std::fabs(v);
    p.t_a = l_c / std::fabs(v) - p.t_c;
    p.y_a = y_start + v / (2 * p.t_a) * p.t_a * p.t_a;
    p.y_b = p.y_a + v * p.t_c;
    p.ok = true;
    return p;
}

VelocityProfile algorithm1(double y_start, double y_end, double l_d, double v) {
    return algorithm1(y_start, y_end, std::fabs(y_end - y_start), l_d, v);
}

ProfileSample sampleProfile(const VelocityProfile& p, double t) {
    ProfileSample s;
    if (!p.ok) return s;
    const double a = p.v / p.t_a;
    if (t <= 0) {
        s.y = p.y_start;
    } else if (t < p.t_a) {
        s.y = p.y_start + 0.5 * a * t * t;
        s.dy = a * t;
        s.ddy = a;
    } else if (t < p.t_a + p.t_c) {
        s.y = p.y_a + p.v * (t - p.t_a);
        s.dy = p.v;
    } else if (t < p.duration()) {
        const double u = t - p.t_a - p.t_c;
        s.y = p.y_b + p.v * u - 0.5 * a * u * u;
        s.dy = p.v - a * u;
        s.ddy = -a;
    } else {
        s.y = p.y_end;
    }
    return s;
}

} // namespace cutcell::quick_return
