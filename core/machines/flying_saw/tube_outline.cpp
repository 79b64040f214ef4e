#include "core/machines/flying_saw/tube_outline.h"

#include "core/common/types.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

TubeOutline TubeOutline::circle(double radius) {
    TubeOutline o;
    o.round = true;
    o.half_width = o.half_height = o.corner_radius = radius;
    return o;
}

TubeOutline TubeOutline::rectangle(double width, double height, double cornerRadius) {
    TubeOutline o;
    o.round = false;
    o.half_width = width / 2;
    o.half_height = height / 2;
    o.corner_radius = cornerRadius;
    return o;
}

TubeOutline TubeOutline::inset(double d) const {
    if (round) return circle(half_width - d);
    TubeOutline o = *this;
    o.half_width -= d;
    o.half_height -= d;
    o.corner_radius = std::max(corner_radius - d, 0.0);
    return o;
}

double TubeOutline::polarRadius(double psi) const {
    if (round) return half_width;
    const double ux = std::cos(psi), uy = std::sin(psi);
    const double A = half_width, B = half_height, r = corner_radius;
    // The sharp rectangle first: the nearer of the two sides the ray meets.
    const double tx = std::fabs(ux) > 1e-300 ? A / std::fabs(ux) : 1e300;
    const double ty = std::fabs(uy) > 1e-300 ? B / std::fabs(uy) : 1e300;
    const double t = std::min(tx, ty);
    const double px = std::fabs(t * ux), py = std::fabs(t * uy);
    if (r <= 0 || px <= A - r || py <= B - r) return t;
    // In the corner square: the far intersection with the corner circle.
    const double cx = A - r, cy = B - r;
    const double ax = std::fabs(ux), ay = std::fabs(uy);
    const double uc = ax * cx + ay * cy;
    const double disc = uc * uc - (cx * cx + cy * cy - r * r);
    return uc + std::sqrt(std::max(disc, 0.0));
}

double TubeOutline::signedDistance(const Eigen::Vector2d& p) const {
    if (round) return p.norm() - half_width;
    const double r = corner_radius;
    const double qx = std::fabs(p.x()) - (half_width - r);
    const double qy = std::fabs(p.y()) - (half_height - r);
    const double outside = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0));
    return outside + std::min(std::max(qx, qy), 0.0) - r;
}

double TubeOutline::maxRadius() const {
    if (round) return half_width;
    const double cx = half_width - corner_radius, cy = half_height - corner_radius;
    return std::hypot(cx, cy) + corner_radius;
}

double TubeOutline::cornerA() const {
    return std::atan2(half_height, -half_width);
}
double TubeOutline::alpha() const {
    return std::atan2(half_width, half_height); // atan(a / b)
}
double TubeOutline::beta() const {
    return std::atan2(half_height, half_width); // atan(b / a)
}

double seedFeed(double a, double b, double theta) {
    const double OA = std::sqrt(a * a + b * b) / 2;
    const double aoe = std::atan(a / b);
    const double aof = 2 * aoe + std::atan(b / a);
    if (theta <= aoe) return OA - b / (2 * std::cos(aoe - theta));     // Eq. 14
    if (theta <= 2 * aoe) return OA - b / (2 * std::cos(theta - aoe)); // Eq. 15
    if (theta <= aof) return OA - a / (2 * std::cos(aof - theta));     // Eq. 16
    return OA - a / (2 * std::cos(theta - aof));                       // Eq. 17
}

} // namespace cutcell
