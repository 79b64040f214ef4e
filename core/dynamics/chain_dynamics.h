#pragma once
// Rigid-body dynamics of a serial chain of up to six revolute joints given by standard
// Denavit-Hartenberg rows (A_i = Rz(theta_i + offset_i) Tz(d_i) Tx(a_i) Rx(alpha_i)):
//
//   M(q) q'' + C(q, q') q' + g(q) = tau
//
// Link i is rigidly attached to DH frame i (the frame after joint i): its centre of mass and
// its inertia tensor (about the centre of mass) are given in that frame, as KDL's Segment does
// for its tip frame. Each joint may add the reflected inertia of its motor and gear
// (N^2 J_rotor, joint side) to the diagonal of M: the usual model of a geared joint, without the
// rotors' gyroscopic coupling.
//
// Algorithms (all quantities in the base frame, fixed-size storage): recursive Newton-Euler for
// the inverse dynamics and the bias forces, the composite-rigid-body algorithm for M (the
// composite's mass, first moment and inertia about the base origin, so that adding a link is a
// sum), a Cholesky factorisation for the forward dynamics. Written out in scalars and 3-vectors:
// one forward dynamics of a 5-joint arm is about 1/3 of the instructions of the same algorithms
// on Eigen's 3 x 3 products (cutcell-cli bench: forward_dynamics_us). SI units throughout (m,
// kg, rad, N m).
//
// Thread safety: const methods may be called from any thread; nothing allocates.
#include "core/common/types.h"

#include <array>
#include <span>

namespace cutcell {

inline constexpr int kMaxChainJoints = 6;

namespace detail {
// A symmetric 3 x 3 matrix (an inertia tensor): the hot loops multiply it by hand.
struct Sym3 {
    double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
};
} // namespace detail

// The inertia of a point mass m at offset d from a reference point, about that point:
// m ((d.d) E - d d^T) (the parallel-axis term when bodies are moved or combined).
Mat3 pointMassInertia(double m, const Vec3& d);

struct ChainJoint {
    double alpha_rad = 0;
    double a_m = 0;
    double d_m = 0;
    double theta_offset_rad = 0;
    // Joint-side reflected rotor inertia N^2 J_rotor (kg m^2), added to M's diagonal.
    double rotor_inertia_kg_m2 = 0;
};

struct LinkInertia {
    double mass_kg = 0;
    Vec3 com_m = Vec3::Zero();         // in the link's DH frame
    Mat3 inertia_kg_m2 = Mat3::Zero(); // about the centre of mass, in the link's DH frame
};

class ChainDynamics {
  public:
    using Vector = Eigen::Matrix<double, kMaxChainJoints, 1>; // entries past size() are 0
    using Matrix = Eigen::Matrix<double, kMaxChainJoints, kMaxChainJoints>;

    ChainDynamics() = default;
    // gravity_m_s2: the gravity vector in the base frame, e.g. (0, 0, -9.81).
    ChainDynamics(std::span<const ChainJoint> joints, std::span<const LinkInertia> links,
                  const Vec3& gravity_m_s2);

    int size() const { return n_; }
    const ChainJoint& joint(int i) const { return joints_[static_cast<size_t>(i)]; }
    const LinkInertia& link(int i) const { return links_[static_cast<size_t>(i)]; }
    const Vec3& gravity() const { return gravity_; }

    // tau = M(q) qdd + C(q, qd) qd + g(q), rotor inertia included.
    void inverseDynamics(const Vector& q, const Vector& qd, const Vector& qdd, Vector& tau) const;
    // M(q), rotor inertia included (symmetric, the upper-left size() x size() block).
    void massMatrix(const Vector& q, Matrix& M) const;
    // C(q, qd) qd + g(q).
    void biasForces(const Vector& q, const Vector& qd, Vector& bias) const;
    // g(q) alone.
    void gravityTorques(const Vector& q, Vector& tau) const;
    // qdd = M(q)^-1 (tau - C(q, qd) qd - g(q)). Returns false if M is not positive definite
    // (a chain without mass on a joint: qdd is then left 0).
    // Options: joints held still (bit i: joint i has qdd = 0, its row and column leave the
    // system) and M's diagonal returned (the joints' effective inertias at q).
    // And M's Cholesky factor returned (lower triangle; a held joint's row and column are the
    // identity's), for solveFactored: M^-1 b at the same state costs two triangular solves.
    struct CholeskyFactor {
        Matrix L;                // lower triangle
        Vector inverse_diagonal; // 1 / L(i, i): the solves multiply instead of divide
    };
    struct ForwardOptions {
        unsigned held_mask = 0;
        Vector* mass_diagonal = nullptr;
        CholeskyFactor* cholesky = nullptr;
    };
    bool forwardDynamics(const Vector& q, const Vector& qd, const Vector& tau, Vector& qdd,
                         const ForwardOptions& options) const;
    bool forwardDynamics(const Vector& q, const Vector& qd, const Vector& tau, Vector& qdd) const {
        return forwardDynamics(q, qd, tau, qdd, ForwardOptions{});
    }

    // x = M^-1 b with M = L L^T as forwardDynamics returned it (held joints: x_i = b_i).
    void solveFactored(const CholeskyFactor& factor, const Vector& b, Vector& x) const;

    // 1/2 qd^T M(q) qd (rotors included) and sum of -m g . c (zero at the base's origin).
    double kineticEnergy(const Vector& q, const Vector& qd) const;
    double potentialEnergy(const Vector& q) const;

  private:
    // Where the links are at q (frame origins o_0 .. o_n, joint axes z_0 .. z_{n-1}, centres of
    // mass, inertias in the base frame): computed once per state, shared by the algorithms.
    struct Kinematics;
    void kinematics(const Vector& q, Kinematics& k) const;
    // Newton-Euler with the kinematics given; gravity scaled by gravityScale (0 or 1).
    void newtonEuler(const Kinematics& k, const Vector& qd, const Vector& qdd, double gravityScale,
                     Vector& tau) const;
    void compositeMassMatrix(const Kinematics& k, Matrix& M) const;

    int n_ = 0;
    std::array<ChainJoint, kMaxChainJoints> joints_{};
    std::array<LinkInertia, kMaxChainJoints> links_{};
    std::array<detail::Sym3, kMaxChainJoints> localInertia_{}; // links_[i].inertia_kg_m2
    std::array<double, kMaxChainJoints> sinAlpha_{}, cosAlpha_{};
    Vec3 gravity_ = Vec3::Zero();
};

} // namespace cutcell
