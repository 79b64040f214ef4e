#include "core/machines/flying_saw/flying_saw_plan.h"

#include "core/common/c_format.h"
#include "core/common/types.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

TubeOutline outerOutline(const FlyingSawSpec& s) {
    return s.shape == TubeShape::Round
               ? TubeOutline::circle(s.diameter_mm / 2)
               : TubeOutline::rectangle(s.width_mm, s.height_mm, s.corner_radius_mm);
}

namespace {

// Largest distance of the blade tip from the cut outline midway between table points (the
// table's Hermite interpolation; the points themselves are on the outline).
double camBetweenPoints(const SawCycle& c) {
    const int n = c.cam.count - 1;
    const double psiA = c.outer.cornerA();
    double worst = 0;
    for (int i = 0; i < n; ++i) {
        const double theta = kPi * (i + 0.5) / n;
        const double rho = c.retract_radius - c.cam.at(theta);
        const double psi = psiA - theta;
        worst = std::max(worst, std::fabs(c.cut.signedDistance(
                                    Eigen::Vector2d(rho * std::cos(psi), rho * std::sin(psi)))));
    }
    return worst;
}

} // namespace

FlyingSawPlan planFlyingSaw(const FlyingSawSpec& spec) {
    FlyingSawPlan p;
    const double V = spec.lineSpeedMmS();
    const double Vmax = V * (1 + spec.line_sim.wander_fraction + spec.line_sim.step_fraction);
    p.line_speed_mm_s = V;
    p.line_speed_max_mm_s = Vmax;
    const CarriageLimits& lim = spec.carriage;
    if (Vmax > lim.max_speed_mm_s) {
        p.problemKey = "carriage.max_speed_mm_s";
        p.problem = messageC("carriage.max_speed_mm_s = %.6g mm/s cannot reach the line: "
                             "line.speed_m_min = %.6g m/min is up to %.6g mm/s with the line's "
                             "wander and steps; the carriage needs >= %.6g mm/s",
                             lim.max_speed_mm_s, spec.line_speed_m_min, Vmax, Vmax);
        return p;
    }
    // BC and EF: the seed's cosine ramp at the highest line speed within acceleration and jerk.
    const double Tramp = rampTime(Vmax, lim);
    p.forward.d1 = Vmax * Tramp;
    p.forward.d3 = p.forward.d1;
    if (std::string why = buildSawCycle(outerOutline(spec), spec.wall_mm, spec.saw, &p.saw);
        !why.empty()) {
        p.problemKey = "machine.saw";
        p.problem = why;
        return p;
    }
    p.cam_max_between_points_mm = camBetweenPoints(p.saw);
    {
        const CamTable& t = p.saw.cam;
        const int n = t.count - 1;
        const double h = t.period / n, w = deg2rad(spec.saw.turntable_deg_s);
        for (int i = 0; i < n; ++i) {
            const auto y = [&](int k) { return t.slave[static_cast<size_t>(((k % n) + n) % n)]; };
            p.feed_accel_peak_mm_s2 =
                std::max(p.feed_accel_peak_mm_s2,
                         std::fabs(y(i + 1) - 2 * y(i) + y(i - 1)) / (h * h) * w * w);
        }
    }
    const double T2 = p.saw.duration();
    p.T1 = p.forward.d1 / V;
    p.T2 = T2;
    p.T3 = p.forward.d3 / V;
    p.stroke_needed_mm = p.forward.d1 / 2 + Vmax * T2 + p.forward.d3 / 2;
    const double available = spec.stroke_mm - spec.wait_position_mm;
    if (p.stroke_needed_mm > available) {
        p.problemKey = "carriage.stroke_mm";
        p.problem = messageC(
            "carriage.stroke_mm = %.6g mm is too short: sync-in %.6g mm + sync and cut %.6g mm "
            "(%.6g s at up to %.6g mm/s) + deceleration %.6g mm need %.6g mm from the wait "
            "position %.6g mm",
            spec.stroke_mm, p.forward.d1 / 2, Vmax * T2, T2, Vmax, p.forward.d3 / 2,
            p.stroke_needed_mm, spec.wait_position_mm);
        return p;
    }
    p.forward_travel_mm = p.forward.d1 / 2 + V * T2 + p.forward.d3 / 2;
    p.reverse = fastestReverse(p.stroke_needed_mm, lim);
    p.nominal_reverse = fastestReverse(p.forward_travel_mm, lim);
    const ReverseProfile& nominalReverse = p.nominal_reverse;
    p.T4 = p.T6 = nominalReverse.ta;
    p.T5 = nominalReverse.ts;
    p.k = nominalReverse.v / V;
    p.cycle_time_s = p.T1 + p.T2 + p.T3 + nominalReverse.duration();
    // The master travels d1 (BC), Vmax T2 (CE), d3 (EF), Vmax T_reverse (FI) from one sync-in
    // to the carriage back at rest; the next sync-in may begin then. 50 ms of margin.
    const double cycleMaster =
        p.forward.d1 + Vmax * T2 + p.forward.d3 + Vmax * (p.reverse.duration() + 0.05);
    p.shortest_length_mm = cycleMaster - spec.blade_kerf_mm;
    for (size_t i = 0; i < spec.queue.size(); ++i) {
        if (spec.queue[i].length_mm < p.shortest_length_mm) {
            p.problemKey = formatC("cut.queue[%zu].length_mm", i);
            p.problem = messageC(
                "cut.queue[%zu].length_mm = %.6g mm is too short for the cycle at %.6g m/min "
                "(up to %.6g mm/s): the shortest possible is %.6g mm (sync-in %.6g mm, sync "
                "and cut %.6g s, deceleration %.6g mm, return %.6g s)",
                i, spec.queue[i].length_mm, spec.line_speed_m_min, Vmax, p.shortest_length_mm,
                p.forward.d1, T2, p.forward.d3, p.reverse.duration());
            return p;
        }
    }
    p.ok = true;
    return p;
}

} // namespace cutcell

namespace cutcell {

double FlyingSawSpec::encoderResolutionMm() const {
    return kPi * roller_diameter_mm / std::max(roller_pulses_per_rev, 1);
}

int FlyingSawSpec::pieceCount() const {
    int n = 0;
    for (const PieceOrder& o : queue)
        n += o.count;
    return n;
}

} // namespace cutcell
