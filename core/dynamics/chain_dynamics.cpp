#include "core/dynamics/chain_dynamics.h"

#include <cmath>
#include <stdexcept>

namespace cutcell {
Mat3 pointMassInertia(double m, const Vec3& d) {
    Mat3 out = -m * d * d.transpose();
    out.diagonal().array() += m * d.squaredNorm();
    return out;
}

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
    }
}

void ChainDynamics::kinematics(const Vector& q, Kinematics& k) const {
    Mat3 R = Mat3::Identity();
    k.origin[0].setZero();
    for (int i = 0; i < n_; ++i) {
        const auto s = static_cast<size_t>(i);
        const ChainJoint& j = joints_[s];
        const double th = q[i] + j.theta_offset_rad;
        const double st = std::sin(th), ct = std::cos(th);
        const double sa = sinAlpha_[s], ca = cosAlpha_[s];
        k.axis[s] = R.col(2);
        k.origin[s + 1] = k.origin[s] + R * Vec3(j.a_m * ct, j.a_m * st, j.d_m);
        Mat3 local;
        local << ct, -st * ca, st * sa, st, ct * ca, -ct * sa, 0, sa, ca;
        R = (R * local).eval();
        k.com[s] = k.origin[s + 1] + R * links_[s].com_m;
        k.inertia[s] = R * links_[s].inertia_kg_m2 * R.transpose();
    }
}

void ChainDynamics::newtonEuler(const Kinematics& k, const Vector& qd, const Vector& qdd,
                                double gravityScale, Vector& tau) const {
    std::array<Vec3, kMaxChainJoints> force, moment; // per link, about its centre of mass
    Vec3 w = Vec3::Zero(), dw = Vec3::Zero();
    // The base accelerates upward at -g: gravity then needs no term of its own.
    Vec3 ao = -gravityScale * gravity_;
    for (int i = 0; i < n_; ++i) {
        const auto s = static_cast<size_t>(i);
        const Vec3& z = k.axis[s];
        dw += z * qdd[i] + w.cross(z) * qd[i];
        w += z * qd[i];
        const Vec3 r = k.origin[s + 1] - k.origin[s];
        ao += dw.cross(r) + w.cross(w.cross(r));
        const Vec3 rc = k.com[s] - k.origin[s + 1];
        const Vec3 ac = ao + dw.cross(rc) + w.cross(w.cross(rc));
        force[s] = links_[s].mass_kg * ac;
        moment[s] = k.inertia[s] * dw + w.cross(k.inertia[s] * w);
    }
    tau.setZero();
    Vec3 f = Vec3::Zero(), m = Vec3::Zero(); // outboard of joint i + 1, moment about o_{i+1}
    for (int i = n_ - 1; i >= 0; --i) {
        const auto s = static_cast<size_t>(i);
        const Vec3& o = k.origin[s];
        m = moment[s] + (k.com[s] - o).cross(force[s]) + m + (k.origin[s + 1] - o).cross(f);
        f += force[s];
        tau[i] = k.axis[s].dot(m) + joints_[s].rotor_inertia_kg_m2 * qdd[i];
    }
}

void ChainDynamics::compositeMassMatrix(const Kinematics& k, Matrix& M) const {
    M.setZero();
    double mc = 0;
    Vec3 cc = Vec3::Zero();
    Mat3 Ic = Mat3::Zero(); // about cc
    for (int j = n_ - 1; j >= 0; --j) {
        const auto s = static_cast<size_t>(j);
        const double mj = links_[s].mass_kg;
        const double m = mc + mj;
        const Vec3 c = m > 0 ? Vec3((mc * cc + mj * k.com[s]) / m) : k.com[s];
        Ic = Ic + pointMassInertia(mc, cc - c) + k.inertia[s] + pointMassInertia(mj, k.com[s] - c);
        mc = m;
        cc = c;
        // Links j.. moving as one body about joint j's axis at unit acceleration, at rest.
        const Vec3& z = k.axis[s];
        const Vec3 F = mc * z.cross(cc - k.origin[s]);
        const Vec3 N = Ic * z;
        for (int i = 0; i <= j; ++i) {
            const auto t = static_cast<size_t>(i);
            const double mij = k.axis[t].dot(N + (cc - k.origin[t]).cross(F));
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
    Matrix L;
    compositeMassMatrix(k, L);
    if (options.mass_diagonal) *options.mass_diagonal = L.diagonal();
    for (int i = 0; i < n_ && options.held_mask; ++i)
        if (options.held_mask & (1u << i)) {
            L.row(i).setZero();
            L.col(i).setZero();
            L(i, i) = 1;
            rhs[i] = 0;
        }
    qdd.setZero();
    // Cholesky L L^T = M in place (lower triangle), then two triangular solves.
    for (int j = 0; j < n_; ++j) {
        double d = L(j, j);
        for (int p = 0; p < j; ++p)
            d -= L(j, p) * L(j, p);
        if (!(d > 0)) return false;
        d = std::sqrt(d);
        L(j, j) = d;
        for (int i = j + 1; i < n_; ++i) {
            double v = L(i, j);
            for (int p = 0; p < j; ++p)
                v -= L(i, p) * L(j, p);
            L(i, j) = v / d;
        }
    }
    for (int i = 0; i < n_; ++i) {
        double v = rhs[i];
        for (int p = 0; p < i; ++p)
            v -= L(i, p) * qdd[p];
        qdd[i] = v / L(i, i);
    }
    for (int i = n_ - 1; i >= 0; --i) {
        double v = qdd[i];
        for (int p = i + 1; p < n_; ++p)
            v -= L(p, i) * qdd[p];
        qdd[i] = v / L(i, i);
    }
    return true;
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
        e -= links_[static_cast<size_t>(i)].mass_kg * gravity_.dot(k.com[static_cast<size_t>(i)]);
    return e;
}

} // namespace cutcell
