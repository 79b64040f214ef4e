#include "core/machines/quick_return/whitworth.h"

#include "core/common/bisect.h"

#include "core/common/c_format.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace cutcell::quick_return {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr int kGrid = 7200; // crank samples per turn for the scans (0.05 deg)

double rhoY(const WhitworthDims& d, double q) {
    const WhitworthPose p = forwardKinematics(d, q);
    return p.closes ? extendedJacobian(d, q, p)[4] : std::numeric_limits<double>::quiet_NaN();
}

double margin(const WhitworthDims& d, double q) {
    return 1 - std::fabs(forwardKinematics(d, q).c);
}

} // namespace

WhitworthDims seedPrintedDims() {
    WhitworthDims d;
    d.o3x = -0.125;
    d.o3y = 0;
    d.r2 = 0.5;
    d.r4 = 0.15;
    d.dx = 0.0705;
    d.ab = 0.08;
    d.scale_offset = 0;
    return d;
}

double wrapAngle(double a) {
    a = std::fmod(a + kPi, 2 * kPi);
    if (a < 0) a += 2 * kPi;
    return a - kPi;
}

WhitworthPose forwardKinematics(const WhitworthDims& d, double q) {
    WhitworthPose p;
    const double ax = d.r2 * std::cos(q) - d.o3x, ay = d.r2 * std::sin(q) - d.o3y;
    p.theta3 = std::atan2(ay, ax);
    p.r3 = std::hypot(ax, ay);
    p.c = (d.dx - d.o3x - (p.r3 + d.ab) * std::cos(p.theta3)) / d.r4;
    p.closes = std::fabs(p.c) <= 1 && p.r3 > 0;
    if (!p.closes) return p;
    p.theta4 = 2 * kPi - std::acos(p.c);
    p.y = d.o3y + (p.r3 + d.ab) * std::sin(p.theta3) + d.r4 * std::sin(p.theta4);
    return p;
}

WhitworthPoints mechanismPoints(const WhitworthDims& d, double q) {
    const WhitworthPose pose = forwardKinematics(d, q);
    WhitworthPoints p;
    p.closes = pose.closes;
    p.o2 = {0, 0};
    p.a = {d.r2 * std::cos(q), d.r2 * std::sin(q)};
    p.o3 = {d.o3x, d.o3y};
    p.b = {d.o3x + (pose.r3 + d.ab) * std::cos(pose.theta3),
           d.o3y + (pose.r3 + d.ab) * std::sin(pose.theta3)};
    p.slider = {d.dx, pose.y};
    return p;
}

std::array<double, 5> extendedJacobian(const WhitworthDims& d, double q, const WhitworthPose& p) {
    const double r2 = d.r2, ab = d.ab, r3 = p.r3, t3 = p.theta3, t4 = p.theta4;
    const double s4 = std::sin(t4);
    return {1.0, -r2 * std::sin(q - t3), r2 * std::cos(q - t3) / r3,
            r2 * (ab * std::sin(q - 2 * t3) - (ab + 2 * r3) * std::sin(q)) / (2 * r3 * d.r4 * s4),
            r2 * (ab * std::sin(q - 2 * t3 + t4) - (ab + 2 * r3) * std::sin(q - t4)) /
                (2 * r3 * s4)};
}

std::array<double, 5> printedJacobian(const WhitworthDims& d, double q, const WhitworthPose& p) {
    std::array<double, 5> rho = extendedJacobian(d, q, p);
    // Row 4 as printed: 2 r3 r2 sin(theta4) in the denominator.
    rho[3] *= d.r4 / d.r2;
    return rho;
}

std::vector<AngleRange> openRanges(const WhitworthDims& d, double* min_margin) {
    std::vector<AngleRange> out;
    double lowest = std::numeric_limits<double>::infinity();
    auto m = [&](double q) { return margin(d, q); };
    bool open = false;
    double from = -kPi;
    double prevQ = -kPi, prevM = m(-kPi);
    if (prevM < 0) open = true;
    lowest = std::min(lowest, prevM);
    for (int i = 1; i <= kGrid; ++i) {
        const double q = -kPi + 2 * kPi * i / kGrid, mq = m(q);
        lowest = std::min(lowest, mq);
        if ((mq < 0) != (prevM < 0)) {
            const double edge = bisect(m, prevQ, q);
            if (mq < 0) {
                from = edge;
                open = true;
            } else {
                out.push_back({from, edge});
                open = false;
            }
        }
        prevQ = q;
        prevM = mq;
    }
    if (open) out.push_back({from, kPi});
    if (min_margin) *min_margin = lowest;
    return out;
}

std::string describeRanges(const std::vector<AngleRange>& ranges) {
    std::string s;
    for (const AngleRange& r : ranges) {
        if (!s.empty()) s += ", ";
        s += formatC("[%.4f, %.4f] rad", r.from, r.to);
    }
    return s;
}

StrokeInfo strokeInfo(const WhitworthDims& d) {
    StrokeInfo s;
    if (!openRanges(d, &s.min_link_margin).empty() || s.min_link_margin <= 0) return s;
    auto rho = [&](double q) { return rhoY(d, q); };
    int found = 0;
    double prevQ = -kPi, prevR = rho(-kPi);
    for (int i = 1; i <= kGrid; ++i) {
        const double q = -kPi + 2 * kPi * i / kGrid, r = rho(q);
        s.max_abs_rho_y = std::max(s.max_abs_rho_y, std::fabs(r));
        if ((r < 0) != (prevR < 0)) {
            const double qs = wrapAngle(bisect(rho, prevQ, q));
            // rho_y from + to - (q increasing): y has its maximum (the top); - to +: the bottom.
            if (prevR > 0)
                s.q_top = qs;
            else
                s.q_bottom = qs;
            ++found;
        }
        prevQ = q;
        prevR = r;
    }
    if (found != 2) return s;
    s.y_top = forwardKinematics(d, s.q_top).y + d.scale_offset;
    s.y_bottom = forwardKinematics(d, s.q_bottom).y + d.scale_offset;
    s.stroke = s.y_top - s.y_bottom;
    s.cut_arc = s.q_bottom - s.q_top;
    if (s.cut_arc < 0) s.cut_arc += 2 * kPi;
    s.return_arc = 2 * kPi - s.cut_arc;
    for (int i = 0; i <= kGrid; ++i)
        s.max_abs_rho_y_cut =
            std::max(s.max_abs_rho_y_cut, std::fabs(rho(s.q_top + s.cut_arc * i / kGrid)));
    s.ok = s.stroke > 0;
    return s;
}

} // namespace cutcell::quick_return
