#pragma once
// The seed-001 groove arm: 5 revolute joints in modified DH (Craig):
//   T_i = Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i)
//   i  alpha_{i-1}  a_{i-1}  d_i    (mm, deg)
//   1      0           0      0
//   2      0        1000      0
//   3     90           0   1110
//   4    -90           0      0
//   5      0         310      0
// The only table with these joint types that reproduces every element of the seed's Eq. (1)
// that is printed consistently (nz, oz, az, ax, px, py, pz) and gives a proper rotation; see
// README "Seed 001 errata". Joints 1 and 2 are parallel (a horizontal 2R arm), joint 3 turns
// about the end of link 2, joint 4 is perpendicular to it, joint 5 is parallel to joint 4 and
// passes through the torch tip (a bevel head that tilts the torch about its nozzle). The torch
// tip is the origin of frame 5 and the torch points along x5 (the seed's n).
#include "core/common/types.h"

#include <array>
#include <string>
#include <vector>

namespace cutcell::section_steel {

using Q5 = std::array<double, 5>;

struct GrooveArmGeometry {
    double a1_mm = 1000; // a_1 (x along link 1)
    double d3_mm = 1110; // d_3 (link 2, along z3)
    double a4_mm = 310;  // a_4 (joint 4 to the torch tip)
};

struct GrooveArmSolution {
    Q5 q{};              // rad, wrapped to (-pi, pi]
    double residual = 0; // |position| mm + |orientation| rad of FK(q) against the target
};

class GrooveArm {
  public:
    GrooveArm() = default;
    explicit GrooveArm(GrooveArmGeometry g) : g_(g) {}
    const GrooveArmGeometry& geometry() const { return g_; }

    // Pose of frame 5 in the base frame; frames(q, out) gives frames 0..5.
    Pose forward(const Q5& q) const;
    void frames(const Q5& q, Pose out[6]) const;

    // All solutions of a full pose (closed form: up to 4; none at the singular s3 = 0 where
    // joints 4/5 are parallel to joints 1/2). Each solution is polished by Gauss-Newton.
    std::vector<GrooveArmSolution> inverse(const Pose& target) const;
    // All solutions that put the torch tip at p pointing along t (unit); the roll about the
    // torch is free (the arm has 5 joints). A 1-D root search over the wrist position.
    std::vector<GrooveArmSolution> inverseTorch(const Vec3& p, const Vec3& t) const;
    // Gauss-Newton from q towards the torch target; true when converged (1e-10 mm / rad).
    bool trackTorch(const Vec3& p, const Vec3& t, Q5& q) const;

  private:
    // 6 x 5 geometric Jacobian (linear rows on top) at the torch tip.
    Eigen::Matrix<double, 6, 5> jacobian(const Q5& q) const;
    bool polish(const Pose* full, const Vec3& p, const Vec3& t, Q5& q, int iterations) const;
    GrooveArmGeometry g_;
};

// Distance of two joint vectors with angles compared modulo 2 pi.
double jointDistance(const Q5& a, const Q5& b);

} // namespace cutcell::section_steel
