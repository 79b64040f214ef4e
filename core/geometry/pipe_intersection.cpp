#include "core/geometry/pipe_intersection.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

PipeIntersection::PipeIntersection(const IntersectionSpec& spec) : spec_(spec) {
    const double a = deg2rad(spec.angle_deg);
    sa_ = std::sin(a);
    ca_ = std::cos(a);
    b_ = Vec3(0, sa_, ca_);
    n_ = Vec3(0, ca_, -sa_);
}

Vec3 PipeIntersection::point(double phi) const {
    const double r = spec_.branch_radius_mm, R = spec_.main_radius_mm;
    const double x = spec_.eccentricity_mm + r * std::sin(phi);
    // Clamp: at |e| + r = R the curve touches y = 0 and rounding must not make the root NaN.
    const double y = spec_.side * std::sqrt(std::max(0.0, R * R - x * x));
    const double t = (y - r * std::cos(phi) * ca_) / sa_;
    const double z = -r * std::cos(phi) * sa_ + t * ca_;
    return {x, y, z};
}

double PipeIntersection::branchAxial(double phi) const {
    const Vec3 p = point(phi);
    return (p - branchOrigin()).dot(b_);
}

bool PipeIntersection::generatrixMeetsMain(double phi) const {
    return std::fabs(spec_.eccentricity_mm + spec_.branch_radius_mm * std::sin(phi)) <=
           spec_.main_radius_mm;
}

Vec3 PipeIntersection::derivative(double phi) const {
    const double r = spec_.branch_radius_mm, R = spec_.main_radius_mm;
    const double x = spec_.eccentricity_mm + r * std::sin(phi);
    const double y = spec_.side * std::sqrt(std::max(0.0, R * R - x * x));
    const double dx = r * std::cos(phi);
    // y dy = -x dx; at the tangency point y -> 0 the slope is unbounded, cap it.
    const double dy = std::fabs(y) > 1e-12 ? -x * dx / y : 0.0;
    const double dt = (dy + r * std::sin(phi) * ca_) / sa_;
    const double dz = r * std::sin(phi) * sa_ + dt * ca_;
    return {dx, dy, dz};
}

double PipeIntersection::mainSurfaceDistance(const Vec3& p) const {
    return std::fabs(std::hypot(p.x(), p.y()) - spec_.main_radius_mm);
}

double PipeIntersection::branchSurfaceDistance(const Vec3& p) const {
    const Vec3 d = p - branchOrigin();
    const Vec3 radial = d - d.dot(b_) * b_;
    return std::fabs(radial.norm() - spec_.branch_radius_mm);
}

} // namespace cutcell
