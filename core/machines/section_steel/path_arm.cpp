#include "core/machines/section_steel/path_arm.h"

#include <cmath>

namespace cutcell::section_steel {

double wrapAngle(double a) {
    a = std::remainder(a, 2 * kPi);
    return a <= -kPi ? a + 2 * kPi : a;
}

PlanarPose PathArm::forward(const std::array<double, 3>& q) const {
    const double t1 = q[0], t12 = q[0] + q[1], t123 = t12 + q[2];
    return {a_[0] * std::cos(t1) + a_[1] * std::cos(t12) + a_[2] * std::cos(t123),
            a_[0] * std::sin(t1) + a_[1] * std::sin(t12) + a_[2] * std::sin(t123), t123};
}

Pose PathArm::forwardPose(const std::array<double, 3>& q) const {
    const PlanarPose p = forward(q);
    Pose T = Pose::Identity();
    T.linear() = Eigen::AngleAxisd(p.phi_rad, Vec3::UnitZ()).toRotationMatrix();
    T.translation() = Vec3(p.x_mm, p.y_mm, 0);
    return T;
}

std::vector<PathArmSolution> PathArm::inverse(const PlanarPose& p) const {
    // Wrist point (end of link 2), then the planar 2R problem.
    const double wx = p.x_mm - a_[2] * std::cos(p.phi_rad);
    const double wy = p.y_mm - a_[2] * std::sin(p.phi_rad);
    const double r2 = wx * wx + wy * wy;
    const double c2 = (r2 - a_[0] * a_[0] - a_[1] * a_[1]) / (2 * a_[0] * a_[1]);
    std::vector<PathArmSolution> out;
    if (!(std::fabs(c2) <= 1 + 1e-12)) return out;
    // s2 from the exact identity 1 - c2^2 = (1 - c2)(1 + c2): better near the boundary.
    const double s2abs = std::sqrt(std::max(0.0, (1 - c2) * (1 + c2)));
    for (double sign : {-1.0, 1.0}) {
        const double s2 = sign * s2abs;
        const double q2 = std::atan2(s2, c2);
        const double q1 = std::atan2(wy, wx) - std::atan2(a_[1] * s2, a_[0] + a_[1] * c2);
        PathArmSolution s;
        s.q = {wrapAngle(q1), wrapAngle(q2), wrapAngle(p.phi_rad - q1 - q2)};
        s.elbow_up = q2 > 0;
        out.push_back(s);
        if (s2abs == 0) break;
    }
    return out;
}

} // namespace cutcell::section_steel
