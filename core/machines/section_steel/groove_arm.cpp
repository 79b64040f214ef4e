#include "core/machines/section_steel/groove_arm.h"

#include "core/machines/section_steel/path_arm.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace cutcell::section_steel {
namespace {

// Modified DH: Rx(alpha) Tx(a) Rz(theta) Tz(d).
Pose mdh(double alpha, double a, double theta, double d) {
    // Exact zeros for alpha = +-90 deg (cos(pi/2) is 6e-17).
    const double ca = std::fabs(alpha) == kPi / 2 ? 0.0 : std::cos(alpha), sa = std::sin(alpha);
    const double ct = std::cos(theta), st = std::sin(theta);
    Pose T = Pose::Identity();
    Eigen::Matrix3d R;
    R << ct, -st, 0, st * ca, ct * ca, -sa, st * sa, ct * sa, ca;
    T.linear() = R;
    T.translation() = Vec3(a, -sa * d, ca * d);
    return T;
}

double poseResidual(const Pose& a, const Pose& b) {
    return (a.translation() - b.translation()).norm() + (a.linear() - b.linear()).norm();
}

Q5 wrapped(Q5 q) {
    for (double& v : q)
        v = wrapAngle(v);
    return q;
}

void addUnique(std::vector<GrooveArmSolution>& out, const GrooveArmSolution& s) {
    for (const auto& o : out)
        if (jointDistance(o.q, s.q) < 1e-7) return;
    out.push_back(s);
}

} // namespace

double jointDistance(const Q5& a, const Q5& b) {
    double s = 0;
    for (size_t i = 0; i < 5; ++i) {
        const double d = wrapAngle(a[i] - b[i]);
        s += d * d;
    }
    return std::sqrt(s);
}

void GrooveArm::frames(const Q5& q, Pose out[6]) const {
    const double alpha[5] = {0, 0, kPi / 2, -kPi / 2, 0};
    const double a[5] = {0, g_.a1_mm, 0, 0, g_.a4_mm};
    const double d[5] = {0, 0, g_.d3_mm, 0, 0};
    out[0] = Pose::Identity();
    for (int i = 0; i < 5; ++i)
        out[i + 1] = out[i] * mdh(alpha[i], a[i], q[static_cast<size_t>(i)], d[i]);
}

Pose GrooveArm::forward(const Q5& q) const {
    Pose f[6];
    frames(q, f);
    return f[5];
}

Eigen::Matrix<double, 6, 5> GrooveArm::jacobian(const Q5& q) const {
    Pose f[6];
    frames(q, f);
    const Vec3 tip = f[5].translation();
    Eigen::Matrix<double, 6, 5> J;
    for (int i = 0; i < 5; ++i) {
        const Vec3 z = f[i + 1].linear().col(2);
        J.block<3, 1>(0, i) = z.cross(tip - f[i + 1].translation());
        J.block<3, 1>(3, i) = z;
    }
    return J;
}

bool GrooveArm::polish(const Pose* full, const Vec3& p, const Vec3& t, Q5& q,
                       int iterations) const {
    for (int it = 0; it < iterations; ++it) {
        const Pose T = forward(q);
        Eigen::Matrix<double, 6, 1> e;
        e.head<3>() = p - T.translation();
        if (full) {
            Vec3 w = Vec3::Zero();
            for (int c = 0; c < 3; ++c)
                w += T.linear().col(c).cross(full->linear().col(c));
            e.tail<3>() = 0.5 * w;
        } else {
            e.tail<3>() = T.linear().col(0).cross(t);
        }
        if (e.head<3>().norm() < 1e-11 && e.tail<3>().norm() < 1e-14) return true;
        const Eigen::Matrix<double, 6, 5> J = jacobian(q);
        const Eigen::Matrix<double, 5, 1> dq = J.colPivHouseholderQr().solve(e);
        if (!dq.allFinite()) return false;
        for (int i = 0; i < 5; ++i)
            q[static_cast<size_t>(i)] += dq[i];
        if (dq.norm() < 1e-15) break;
    }
    const Pose T = forward(q);
    const double ep = (p - T.translation()).norm();
    const double eo = full ? (T.linear() - full->linear()).norm() : (T.linear().col(0) - t).norm();
    return ep < 1e-9 && eo < 1e-11;
}

std::vector<GrooveArmSolution> GrooveArm::inverse(const Pose& target) const {
    const Eigen::Matrix3d& R = target.linear();
    const Vec3 n = R.col(0), o = R.col(1), a = R.col(2), p = target.translation();
    std::vector<GrooveArmSolution> out;
    const double s3abs = std::hypot(a.x(), a.y());
    if (s3abs < 1e-9) return out; // singular: theta3 = 0 or pi
    const double A1 = g_.a1_mm, D3 = g_.d3_mm, A4 = g_.a4_mm;
    for (double sigma : {1.0, -1.0}) {
        const double s3 = sigma * s3abs, c3 = a.z();
        const double th3 = std::atan2(s3, c3);
        const double th12 = std::atan2(-sigma * a.y(), -sigma * a.x());
        const double th45 = std::atan2(-sigma * o.z(), sigma * n.z());
        // Position in the frame turned by theta1 + theta2:
        //   Qx = a1 c2 + a4 c3 c4,  Qy = -a1 s2 - d3 + a4 s4,  Qz = a4 s3 c4.
        const double c12 = std::cos(th12), s12 = std::sin(th12);
        const double Qx = c12 * p.x() + s12 * p.y(), Qy = -s12 * p.x() + c12 * p.y();
        const double Qz = p.z(), B0 = Qy + D3;
        // |(Qx - a4 c3 c4, B0 - a4 s4)| = a1 with a4^2 (c3^2 c4^2 + s4^2) = a4^2 - Qz^2:
        //   alpha c4 + beta s4 = gamma.
        const double al = -2 * A4 * Qx * c3, be = -2 * A4 * B0;
        const double ga = A1 * A1 - Qx * Qx - B0 * B0 - A4 * A4 + Qz * Qz;
        std::vector<double> th4s;
        const double rho = std::hypot(al, be);
        if (rho > 1e-12) {
            const double c = std::clamp(ga / rho, -1.0, 1.0);
            const double base = std::atan2(be, al), off = std::acos(c);
            th4s = {base + off, base - off};
        }
        const double c4 = Qz / (A4 * s3);
        if (std::fabs(be) > 1e-12 && std::fabs(c4) <= 1) {
            th4s.push_back(std::atan2((ga - al * c4) / be, c4));
        }
        for (double th4 : th4s) {
            const double cc4 = std::cos(th4), ss4 = std::sin(th4);
            const double th2 = std::atan2(-(B0 - A4 * ss4) / A1, (Qx - A4 * c3 * cc4) / A1);
            Q5 q = {th12 - th2, th2, th3, th4, th45 - th4};
            if (poseResidual(forward(q), target) > 1e-4) continue;
            polish(&target, p, n, q, 4);
            q = wrapped(q);
            GrooveArmSolution s{q, poseResidual(forward(q), target)};
            if (s.residual < 1e-8) addUnique(out, s);
        }
    }
    return out;
}

bool GrooveArm::trackTorch(const Vec3& p, const Vec3& t, Q5& q) const {
    const bool ok = polish(nullptr, p, t, q, 12);
    q = wrapped(q);
    return ok;
}

std::vector<GrooveArmSolution> GrooveArm::inverseTorch(const Vec3& p, const Vec3& tIn) const {
    std::vector<GrooveArmSolution> out;
    const Vec3 t = tIn.normalized();
    const double A1 = g_.a1_mm, D3 = g_.d3_mm, A4 = g_.a4_mm;
    if (std::fabs(p.z()) > A4) return out;
    const double rho = std::sqrt(A4 * A4 - p.z() * p.z());
    // The wrist W (origin of frame 4, z = 0) lies on a circle of radius rho about p; a 2R arm
    // (a1 along theta1, d3 along theta12 - 90 deg) reaches it in two elbow branches. The axis
    // a = z4 must be normal to both the torch and (p - W), and its horizontal part must lie
    // along (cos theta12, sin theta12): f(psi) = 0.
    struct Eval {
        bool ok = false;
        double f = 0, th1 = 0, th12 = 0;
        Vec3 d{0, 0, 0};
    };
    auto eval = [&](double psi, double elbow) {
        Eval e;
        const Vec3 W(p.x() + rho * std::cos(psi), p.y() + rho * std::sin(psi), 0);
        const double r2 = W.x() * W.x() + W.y() * W.y();
        const double c = (r2 - A1 * A1 - D3 * D3) / (2 * A1 * D3);
        if (std::fabs(c) > 1) return e;
        const double s = elbow * std::sqrt((1 - c) * (1 + c));
        const double rel = std::atan2(s, c); // phi - theta1, phi = theta12 - pi/2
        e.th1 = std::atan2(W.y(), W.x()) - std::atan2(D3 * s, A1 + D3 * c);
        e.th12 = e.th1 + rel + kPi / 2;
        e.d = p - W;
        const Vec3 m = e.d.cross(t);
        e.f = -m.x() * std::sin(e.th12) + m.y() * std::cos(e.th12);
        e.f /= std::max(1e-300, m.norm());
        e.ok = m.norm() > 1e-9 * A4;
        return e;
    };
    auto finish = [&](double psi, double elbow) {
        const Eval e = eval(psi, elbow);
        if (!e.ok) return;
        const Vec3 m = e.d.cross(t).normalized();
        const double c12 = std::cos(e.th12), s12 = std::sin(e.th12);
        const Vec3 y2(-s12, c12, 0);
        for (double sign : {1.0, -1.0}) {
            const Vec3 a = sign * m;
            const double s3 = -(a.x() * c12 + a.y() * s12), c3 = a.z();
            const double th3 = std::atan2(s3, c3);
            const Vec3 x3(c12 * c3, s12 * c3, s3);
            const Vec3 dh = e.d / A4;
            const double th4 = std::atan2(dh.dot(y2), dh.dot(x3));
            const double th45 = std::atan2(t.dot(y2), t.dot(x3));
            Q5 q = {e.th1, e.th12 - e.th1, th3, th4, th45 - th4};
            if (!polish(nullptr, p, t, q, 12)) continue;
            q = wrapped(q);
            const Pose T = forward(q);
            addUnique(out, {q, (T.translation() - p).norm() + (T.linear().col(0) - t).norm()});
        }
    };
    constexpr int kSteps = 720;
    // A root at the end of a reachable stretch of the circle (the 2R arm stretched or folded,
    // where its two elbow branches meet) shows as a sign change across the fold, not along
    // one branch (or as two roots close together): start Gauss-Newton from both branches.
    {
        Eval prev = eval(0, 1.0);
        for (int k = 1; k <= kSteps; ++k) {
            const double psi = 2 * kPi * k / kSteps;
            const Eval cur = eval(psi, 1.0);
            if (prev.ok != cur.ok) {
                const double psiOk = prev.ok ? 2 * kPi * (k - 1) / kSteps : psi;
                double in = psiOk, outPsi = prev.ok ? psi : 2 * kPi * (k - 1) / kSteps;
                for (int it = 0; it < 50; ++it) {
                    const double mid = 0.5 * (in + outPsi);
                    (eval(mid, 1.0).ok ? in : outPsi) = mid;
                }
                for (double w : {0.0, 0.25, 0.5, 1.0})
                    for (double elbow : {1.0, -1.0})
                        finish(in + w * (psiOk - in), elbow);
            }
            prev = cur;
        }
    }
    for (double elbow : {1.0, -1.0}) {
        Eval prev = eval(0, elbow);
        double prevPsi = 0;
        for (int k = 1; k <= kSteps; ++k) {
            const double psi = 2 * kPi * k / kSteps;
            const Eval cur = eval(psi, elbow);
            if (prev.ok && cur.ok && (prev.f == 0 || (prev.f < 0) != (cur.f < 0))) {
                // Bisection (f is continuous on a reachable stretch of the circle).
                double lo = prevPsi, hi = psi, flo = prev.f;
                for (int it = 0; it < 60; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    const Eval em = eval(mid, elbow);
                    if (!em.ok) break;
                    if ((em.f < 0) == (flo < 0)) {
                        lo = mid;
                        flo = em.f;
                    } else {
                        hi = mid;
                    }
                }
                finish(0.5 * (lo + hi), elbow);
            }
            prev = cur;
            prevPsi = psi;
        }
    }
    return out;
}

} // namespace cutcell::section_steel
