#include "core/dynamics/chain_dynamics.h"
#include "core/common/sin_cos.h"

#include <cmath>
#include <stdexcept>

namespace cutcell {
Mat3 pointMassInertia(double m, const Vec3& d) {
    Mat3 out = -m * d * d.transpose();
    out.diagonal().array() += m * d.squaredNorm();
    return out;
}

namespace {
using detail::Sym3;

// A 3-vector in plain scalars: the compiler keeps these in registers, where Eigen's 3-vectors
// on SSE2 cost a third more time in these loops (measured with the forward dynamics bench).
struct V3 {
    double x = 0, y = 0, z = 0;
    V3() = default;
    constexpr V3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
    explicit V3(const Vec3& v) : x(v.x()), y(v.y()), z(v.z()) {}
    V3& operator+=(const V3& o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    double dot(const V3& o) const { return x * o.x + y * o.y + z * o.z; }
    double squaredNorm() const { return dot(*this); }
    V3 cross(const V3& o) const {
        return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x};
    }
};
inline V3 operator+(const V3& a, const V3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline V3 operator-(const V3& a, const V3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline V3 operator*(double s, const V3& a) {
    return {s * a.x, s * a.y, s * a.z};
}
inline V3 operator*(const V3& a, double s) {
    return {s * a.x, s * a.y, s * a.z};
}

inline V3 times(const Sym3& I, const V3& v) {
    return V3(I.xx * v.x + I.xy * v.y + I.xz * v.z, I.xy * v.x + I.yy * v.y + I.yz * v.z,
              I.xz * v.x + I.yz * v.y + I.zz * v.z);
}

// R I R^T for the rotation R = [X Y Z] (its columns) and I given in the rotated frame.
inline Sym3 rotated(const Sym3& I, const V3& X, const V3& Y, const V3& Z) {
    // The columns of R I (a tensor on the frame's principal axes, the common case, saves two
    // thirds of the products).
    const bool principal = I.xy == 0 && I.xz == 0 && I.yz == 0;
    const V3 a0 = principal ? I.xx * X : I.xx * X + I.xy * Y + I.xz * Z;
    const V3 a1 = principal ? I.yy * Y : I.xy * X + I.yy * Y + I.yz * Z;
    const V3 a2 = principal ? I.zz * Z : I.xz * X + I.yz * Y + I.zz * Z;
    return {a0.x * X.x + a1.x * Y.x + a2.x * Z.x, a0.y * X.y + a1.y * Y.y + a2.y * Z.y,
            a0.z * X.z + a1.z * Y.z + a2.z * Z.z, a0.x * X.y + a1.x * Y.y + a2.x * Z.y,
            a0.x * X.z + a1.x * Y.z + a2.x * Z.z, a0.y * X.z + a1.y * Y.z + a2.y * Z.z};
}

// I += I_c + m ((d.d) E - d d^T): a body's inertia moved from its centre of mass to a point at
// -d from it, added to I.
inline void addBody(Sym3& I, const Sym3& Ic, double m, const V3& d) {
    const double dd = d.squaredNorm();
    I.xx += Ic.xx + m * (dd - d.x * d.x);
    I.yy += Ic.yy + m * (dd - d.y * d.y);
    I.zz += Ic.zz + m * (dd - d.z * d.z);
    I.xy += Ic.xy - m * d.x * d.y;
    I.xz += Ic.xz - m * d.x * d.z;
    I.yz += Ic.yz - m * d.y * d.z;
}

} // namespace

struct ChainDynamics::Kinematics {
    std::array<V3, kMaxChainJoints + 1> origin;
    std::array<V3, kMaxChainJoints> axis;
    std::array<V3, kMaxChainJoints> com;
    std::array<Sym3, kMaxChainJoints> inertia; // about the centre of mass, base frame
};

ChainDynamics::ChainDynamics(std::span<const ChainJoint> joints, std::span<const LinkInertia> links,
                             const Vec3& gravity_m_s2)
    : n_(static_cast<int>(joints.size())), gravity_(gravity_m_s2) {
    if (joints.size() > static_cast<size_t>(kMaxChainJoints) || joints.size() != links.size())
        throw std::invalid_argument("ChainDynamics: 1..6 joints, one link per joint");
    for (size_t i = 0; i < joints.size(); ++i) {
        joints_[i] = joints[i];
        links_[i] = links[i];
        sinAlpha_[i] = std::sin(joints[i].alpha_rad);
        cosAlpha_[i] = std::cos(joints[i].alpha_rad);
        const Mat3& I = links[i].inertia_kg_m2;
        // The symmetric part (a tensor given slightly asymmetric counts as its mean).
        localInertia_[i] = {I(0, 0),
                            I(1, 1),
                            I(2, 2),
                            0.5 * (I(0, 1) + I(1, 0)),
                            0.5 * (I(0, 2) + I(2, 0)),
                            0.5 * (I(1, 2) + I(2, 1))};
    }
}

void ChainDynamics::kinematics(const Vector& q, Kinematics& k) const {
    // The frame's axes as columns of R_0^i: A_i = Rz(theta) Tz(d) Tx(a) Rx(alpha) turns x, y
    // about z by theta, then y, z about the new x by alpha.
    V3 X = V3(1, 0, 0), Y = V3(0, 1, 0), Z = V3(0, 0, 1);
    k.origin[0] = V3();
    for (int i = 0; i < n_; ++i) {
        const auto s = static_cast<size_t>(i);
        const ChainJoint& j = joints_[s];
        const double th = q[i] + j.theta_offset_rad;
        double st, ct;
        sinCos(th, st, ct);
        const double sa = sinAlpha_[s], ca = cosAlpha_[s];
        k.axis[s] = Z;
        const V3 Xn = ct * X + st * Y;
        const V3 Yz = ct * Y - st * X; // y after the turn about z
        k.origin[s + 1] = k.origin[s] + j.a_m * Xn + j.d_m * Z;
        X = Xn;
        Y = ca * Yz + sa * Z;
        Z = ca * Z - sa * Yz;
        const V3 c(links_[s].com_m);
        k.com[s] = k.origin[s + 1] + c.x * X + c.y * Y + c.z * Z;
        k.inertia[s] = rotated(localInertia_[s], X, Y, Z);
    }
}

void ChainDynamics::newtonEuler(const Kinematics& k, const Vector& qd, const Vector& qdd,
                                double gravityScale, Vector& tau) const {
    std::array<V3, kMaxChainJoints> force, moment; // per link, about its centre of mass
    V3 w = V3(), dw = V3();
    // The base accelerates upward at -g: gravity then needs no term of its own.
    V3 ao = -gravityScale * V3(gravity_);
    // The centripetal term w x (w x r) = w (w . r) - r (w . w).
    auto centripetal = [](const V3& u, double uu, const V3& r) { return u * u.dot(r) - r * uu; };
    for (int i = 0; i < n_; ++i) {
        const auto s = static_cast<size_t>(i);
        const V3& z = k.axis[s];
        dw += z * qdd[i] + w.cross(z) * qd[i];
        w += z * qd[i];
        const double ww = w.squaredNorm();
        const V3 r = k.origin[s + 1] - k.origin[s];
        ao += dw.cross(r) + centripetal(w, ww, r);
        const V3 rc = k.com[s] - k.origin[s + 1];
        const V3 ac = ao + dw.cross(rc) + centripetal(w, ww, rc);
        force[s] = links_[s].mass_kg * ac;
        moment[s] = times(k.inertia[s], dw) + w.cross(times(k.inertia[s], w));
    }
    tau.setZero();
    V3 f = V3(), m = V3(); // outboard of joint i + 1, moment about o_{i+1}
    for (int i = n_ - 1; i >= 0; --i) {
        const auto s = static_cast<size_t>(i);
        const V3& o = k.origin[s];
        m = moment[s] + (k.com[s] - o).cross(force[s]) + m + (k.origin[s + 1] - o).cross(f);
        f += force[s];
        tau[i] = k.axis[s].dot(m) + joints_[s].rotor_inertia_kg_m2 * qdd[i];
    }
}

void ChainDynamics::compositeMassMatrix(const Kinematics& k, Matrix& M) const {
    // M(i, j), i <= j: the moment about joint i's axis that links j.. need to turn, as one
    // body at rest, about joint j's axis (z_j through o_j) at unit acceleration. With the
    // composite's mass m, first moment h and inertia J about the base origin, its angular
    // momentum about a point P for a unit rate about that axis is
    //   L_P = J z_j - h x (z_j x o_j) - P x (z_j x (h - m o_j)),
    // so M(i, j) = z_i . u_j - (z_i x o_i) . w_j with u_j = J z_j - h x (z_j x o_j) and
    // w_j = z_j x (h - m o_j).
    M.setZero();
    std::array<V3, kMaxChainJoints> zxo;
    for (int i = 0; i < n_; ++i)
        zxo[static_cast<size_t>(i)] =
            k.axis[static_cast<size_t>(i)].cross(k.origin[static_cast<size_t>(i)]);
    double mass = 0;
    V3 h = V3();
    Sym3 J;
    for (int j = n_ - 1; j >= 0; --j) {
        const auto s = static_cast<size_t>(j);
        const double mj = links_[s].mass_kg;
        mass += mj;
        h += mj * k.com[s];
        addBody(J, k.inertia[s], mj, k.com[s]);
        const V3& z = k.axis[s];
        const V3& o = k.origin[s];
        const V3 u = times(J, z) - h.cross(z.cross(o));
        const V3 w = z.cross(h - mass * o);
        for (int i = 0; i <= j; ++i) {
            const auto t = static_cast<size_t>(i);
            const double mij = k.axis[t].dot(u) - zxo[t].dot(w);
            M(i, j) = mij;
            M(j, i) = mij;
        }
        M(j, j) += joints_[s].rotor_inertia_kg_m2;
    }
}

void ChainDynamics::inverseDynamics(const Vector& q, const Vector& qd, const Vector& qdd,
                                    Vector& tau) const {
    Kinematics k;
    kinematics(q, k);
    newtonEuler(k, qd, qdd, 1.0, tau);
}

void ChainDynamics::massMatrix(const Vector& q, Matrix& M) const {
    Kinematics k;
    kinematics(q, k);
    compositeMassMatrix(k, M);
}

void ChainDynamics::biasForces(const Vector& q, const Vector& qd, Vector& bias) const {
    Kinematics k;
    kinematics(q, k);
    newtonEuler(k, qd, Vector::Zero(), 1.0, bias);
}

void ChainDynamics::gravityTorques(const Vector& q, Vector& tau) const {
    Kinematics k;
    kinematics(q, k);
    newtonEuler(k, Vector::Zero(), Vector::Zero(), 1.0, tau);
}

bool ChainDynamics::forwardDynamics(const Vector& q, const Vector& qd, const Vector& tau,
                                    Vector& qdd, const ForwardOptions& options) const {
    Kinematics k;
    kinematics(q, k);
    Vector rhs;
    newtonEuler(k, qd, Vector::Zero(), 1.0, rhs);
    rhs = tau - rhs;
    CholeskyFactor local;
    CholeskyFactor& factor = options.cholesky ? *options.cholesky : local;
    Matrix& L = factor.L;
    compositeMassMatrix(k, L);
    if (options.mass_diagonal) *options.mass_diagonal = L.diagonal();
    for (int i = 0; i < n_ && options.held_mask; ++i)
        if (options.held_mask & (1u << i)) {
            L.row(i).setZero();
            L.col(i).setZero();
            L(i, i) = 1;
            rhs[i] = 0;
        }
    // Cholesky L L^T = M in place (lower triangle), then two triangular solves.
    for (int j = 0; j < n_; ++j) {
        double d = L(j, j);
        for (int p = 0; p < j; ++p)
            d -= L(j, p) * L(j, p);
        if (!(d > 0)) {
            qdd.setZero();
            return false;
        }
        d = std::sqrt(d);
        L(j, j) = d;
        const double inverse = 1 / d;
        factor.inverse_diagonal[j] = inverse;
        for (int i = j + 1; i < n_; ++i) {
            double v = L(i, j);
            for (int p = 0; p < j; ++p)
                v -= L(i, p) * L(j, p);
            L(i, j) = v * inverse;
        }
    }
    solveFactored(factor, rhs, qdd);
    return true;
}

namespace {
// The two triangular solves for a compile-time size N (unrolled: the integrator runs four of
// them per step).
template <int N>
void solveCholesky(const ChainDynamics::CholeskyFactor& factor, const ChainDynamics::Vector& b,
                   ChainDynamics::Vector& x) {
    const auto& L = factor.L;
    const auto& inverse = factor.inverse_diagonal;
    x.setZero();
    for (int i = 0; i < N; ++i) {
        double v = b[i];
        for (int p = 0; p < i; ++p)
            v -= L(i, p) * x[p];
        x[i] = v * inverse[i];
    }
    for (int i = N - 1; i >= 0; --i) {
        double v = x[i];
        for (int p = i + 1; p < N; ++p)
            v -= L(p, i) * x[p];
        x[i] = v * inverse[i];
    }
}
} // namespace

void ChainDynamics::solveFactored(const CholeskyFactor& factor, const Vector& b, Vector& x) const {
    switch (n_) {
    case 1:
        solveCholesky<1>(factor, b, x);
        break;
    case 2:
        solveCholesky<2>(factor, b, x);
        break;
    case 3:
        solveCholesky<3>(factor, b, x);
        break;
    case 4:
        solveCholesky<4>(factor, b, x);
        break;
    case 5:
        solveCholesky<5>(factor, b, x);
        break;
    default:
        solveCholesky<6>(factor, b, x);
        break;
    }
}

double ChainDynamics::kineticEnergy(const Vector& q, const Vector& qd) const {
    Matrix M;
    massMatrix(q, M);
    return 0.5 * qd.dot(M * qd);
}

double ChainDynamics::potentialEnergy(const Vector& q) const {
    Kinematics k;
    kinematics(q, k);
    double e = 0;
    for (int i = 0; i < n_; ++i)
        e -= links_[static_cast<size_t>(i)].mass_kg *
             V3(gravity_).dot(k.com[static_cast<size_t>(i)]);
    return e;
}

} // namespace cutcell
