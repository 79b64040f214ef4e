#pragma once
// The seed-001 cutting-path arm: a planar 3R chain in standard DH (Robotics Toolbox
// `link([0, a, 0])` = alpha 0, a, d 0) with a1 = 1000, a2 = 1110, a3 = 310 mm. The seed prints
// the lengths as 100000 / 111000 / 31000 (decimal points lost in print). The torch tip is the
// end of link 3 and the torch points along link 3 (phi = q1 + q2 + q3).
#include "core/common/types.h"

#include <array>
#include <vector>

namespace cutcell::section_steel {

struct PlanarPose {
    double x_mm = 0, y_mm = 0; // tip in the arm's base plane
    double phi_rad = 0;        // direction of the last link (and of the torch)
};

struct PathArmSolution {
    std::array<double, 3> q{}; // rad, wrapped to (-pi, pi]
    bool elbow_up = false;     // q2 > 0
};

class PathArm {
  public:
    PathArm() = default;
    PathArm(double a1, double a2, double a3) : a_{a1, a2, a3} {}
    const std::array<double, 3>& lengths() const { return a_; }

    PlanarPose forward(const std::array<double, 3>& q) const;
    // The full homogeneous transform of the chain (z along the joint axes).
    Pose forwardPose(const std::array<double, 3>& q) const;
    // Both elbow branches (one when the wrist is on the workspace boundary, none outside).
    std::vector<PathArmSolution> inverse(const PlanarPose& p) const;

  private:
    std::array<double, 3> a_{1000, 1110, 310};
};

double wrapAngle(double a); // to (-pi, pi]

} // namespace cutcell::section_steel
