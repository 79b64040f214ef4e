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

// Every solution of a torch target (GrooveArm::solveTorch), or why there is none.
struct GrooveTorchIk {
    std::vector<GrooveArmSolution> solutions;
    // Empty when `solutions` is the complete (finite) set. Otherwise, in words: why there is no
    // solution (the tip out of reach, with its distance and the reachable range in mm; a torch
    // direction the arm cannot point at there, with how far off the nearest one is), or why
    // `solutions` is only a sample (`continuum`: a singular pose with infinitely many).
    std::string why;
    bool continuum = false;
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
    // All solutions that put the torch tip at p pointing along t (unit), both in the base
    // frame; the roll about the torch is not a joint (5 constraints, 5 joints). Closed form:
    // phi = theta1 + theta2 is a root of a trigonometric polynomial of degree 4 (up to 8 roots,
    // from the eigenvalues of its companion matrix), each root gives theta2 and two theta3
    // (theta3 + pi with theta4, theta5 to match): up to 16 solutions, each checked by FK
    // (tip < 1e-6 mm, direction < 1e-9) and polished by Gauss-Newton where it needs it; a
    // root where the closed form is ill-conditioned seeds Gauss-Newton from the tip alone. A
    // torch within 1e-3 of horizontal (where the roots crowd together in pairs) is also solved
    // from its horizontal neighbour's solutions by Gauss-Newton. Singular poses with a
    // continuum of solutions (the torch horizontal and the tip in the plane z = 0, to within
    // 1e-9; tip and torch on joint 1's axis): `continuum`, a sample 5 deg apart, and `why`.
    // No solution: `why` (the tip out of reach, or the direction, in mm and deg).
    GrooveTorchIk solveTorch(const Vec3& p, const Vec3& t) const;
    std::vector<GrooveArmSolution> inverseTorch(const Vec3& p, const Vec3& t) const {
        return solveTorch(p, t).solutions;
    }
    // Tip and torch direction (x5) at q in the base frame (closed form, cheaper than forward).
    void torch(const Q5& q, Vec3& p, Vec3& t) const;
    // Gauss-Newton from q towards the torch target (the roll about the torch left free); true
    // when converged (1e-9 mm, 1e-11).
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
