#include "core/machines/section_steel/groove_arm.h"

#include "core/common/c_format.h"
#include "core/machines/section_steel/path_arm.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>

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

void addUnique(std::vector<GrooveArmSolution>& out, const GrooveArmSolution& s,
               double spacing = 1e-7) {
    for (const auto& o : out)
        if (jointDistance(o.q, s.q) < spacing) return;
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
        Eigen::Matrix<double, 6, 5> J = jacobian(q);
        if (full) {
            Vec3 w = Vec3::Zero();
            for (int c = 0; c < 3; ++c)
                w += T.linear().col(c).cross(full->linear().col(c));
            e.tail<3>() = 0.5 * w;
        } else {
            // The torch direction: its change z_i x x5, not the turn about it (the roll is
            // free: rows of angular velocity would ask for a zero roll and stall Gauss-Newton
            // at linear convergence).
            const Vec3 x5 = T.linear().col(0);
            e.tail<3>() = t - x5;
            for (int i = 0; i < 5; ++i)
                J.block<3, 1>(3, i) = Vec3(J.block<3, 1>(3, i)).cross(x5);
        }
        if (e.head<3>().norm() < 1e-11 && e.tail<3>().norm() < 1e-14) return true;
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

bool GrooveArm::trackTorch(const Vec3& p, const Vec3& tIn, Q5& q) const {
    // The step compares directions (t - x5): t must be a unit vector.
    const double n = tIn.norm();
    if (!(n > 0) || !std::isfinite(n)) return false;
    const bool ok = polish(nullptr, p, tIn / n, q, 12);
    q = wrapped(q);
    return ok;
}

void GrooveArm::torch(const Q5& q, Vec3& p, Vec3& t) const {
    const double A1 = g_.a1_mm, D3 = g_.d3_mm, A4 = g_.a4_mm;
    const double phi = q[0] + q[1];
    const double c1 = std::cos(q[0]), s1 = std::sin(q[0]), cf = std::cos(phi), sf = std::sin(phi);
    const double c3 = std::cos(q[2]), s3 = std::sin(q[2]), c4 = std::cos(q[3]), s4 = std::sin(q[3]);
    const double c5 = std::cos(q[4]), s5 = std::sin(q[4]);
    const Vec3 x3(c3 * cf, c3 * sf, s3), z3(sf, -cf, 0);
    const Vec3 x4 = c4 * x3 - s4 * z3, y4 = -s4 * x3 - c4 * z3;
    p = Vec3(A1 * c1, A1 * s1, 0) + D3 * z3 + A4 * x4;
    t = c5 * x4 + s5 * y4;
}

// The torch IK in closed form. With phi = theta1 + theta2 (frame 3's origin o3 = o4 lies in
// the base plane z = 0):
//   o3 = a1 (c1, s1, 0) + d3 z3,  z3 = (s_phi, -c_phi, 0),
//   z4 = z5 = y3 = -s3 (c_phi, s_phi, 0) + c3 (0, 0, 1),  tip p = o3 + a4 x4,  torch t = x5,
// and x4, x5 are normal to z4. So, with u = c_phi px + s_phi py, v = s_phi px - c_phi py,
// tau = c_phi tx + s_phi ty, w = v - d3, K = (|p|^2 + a1^2 + d3^2 - a4^2) / 2 - d3 v:
//   (i)   z4 . t = 0:          (s3, c3) = +-(tz, tau) / |(tz, tau)|,
//   (ii)  z4 . (p - o3) = 0:   with (i), tz X = C := u tz - tau pz,
//   (iii) |p - o3| = a4:       u X + w Y = K,
// where (X, Y) = a1 (c2, s2). X^2 + Y^2 = a1^2 then gives
//   P(phi) = C^2 w^2 + (tz K - u C)^2 - a1^2 tz^2 w^2 = 0,
// a trigonometric polynomial of degree 4 in phi: up to 8 real roots, each with two theta3.
namespace {

struct TorchEq {
    double px, py, pz, tx, ty, tz, A1, D3, K0;
    struct At {
        double c, s, u, v, tau, C, K, w, E, P, terms;
    };
    At at(double c, double s) const {
        At a;
        a.c = c;
        a.s = s;
        a.u = c * px + s * py;
        a.v = s * px - c * py;
        a.tau = c * tx + s * ty;
        a.C = a.u * tz - a.tau * pz;
        a.K = K0 - D3 * a.v;
        a.w = a.v - D3;
        a.E = tz * a.K - a.u * a.C;
        const double cw = a.C * a.w, tw = A1 * tz * a.w;
        a.P = cw * cw + a.E * a.E - tw * tw;
        a.terms = cw * cw + a.E * a.E + tw * tw;
        return a;
    }
    At at(double phi) const { return at(std::cos(phi), std::sin(phi)); }
    double dP(const At& a) const {
        const double du = -a.v, dv = a.u, dtau = -a.s * tx + a.c * ty;
        const double dC = du * tz - dtau * pz, dK = -D3 * dv, dw = dv;
        const double dE = tz * dK - du * a.C - a.u * dC;
        return 2 * a.C * a.w * (dC * a.w + a.C * dw) + 2 * a.E * dE -
               2 * A1 * A1 * tz * tz * a.w * dw;
    }
};

// (1 + x^2)^4 e^{i k psi} with x = tan(psi / 2) is (1 + ix)^(4 + k) (1 - ix)^(4 - k): its
// coefficients of x^0 .. x^8 for k = 0..4; and cos / sin of the 9 sample angles 2 pi j / 9.
struct TorchTables {
    std::complex<double> half[5][9];
    double c9[9], s9[9];
    TorchTables() {
        for (int k = 0; k <= 4; ++k) {
            std::complex<double> poly[9] = {1.0};
            int deg = 0;
            auto times = [&](std::complex<double> b) { // poly *= (1 + b x)
                for (int m = deg + 1; m >= 1; --m)
                    poly[m] += b * poly[m - 1];
                ++deg;
            };
            for (int i = 0; i < 4 + k; ++i)
                times({0, 1});
            for (int i = 0; i < 4 - k; ++i)
                times({0, -1});
            for (int m = 0; m < 9; ++m)
                half[k][m] = poly[m];
        }
        for (int j = 0; j < 9; ++j) {
            c9[j] = std::cos(2 * kPi * j / 9);
            s9[j] = std::sin(2 * kPi * j / 9);
        }
    }
};

const TorchTables& torchTables() {
    static const TorchTables tables;
    return tables;
}

// Points (X, Y) on the circle of radius r with u X + w Y = K: 0, 1 or 2. A line that misses
// the circle by less than `slack` (relative) gives the circle's point nearest to it.
int lineCircle(double u, double w, double K, double r, double slack, double X[2], double Y[2]) {
    const double n = std::hypot(u, w);
    if (!(n > 0)) return 0;
    double c = K / (r * n);
    if (!(std::fabs(c) <= 1 + slack)) return 0;
    c = std::clamp(c, -1.0, 1.0);
    const double base = std::atan2(w, u), off = std::acos(c);
    X[0] = r * std::cos(base + off);
    Y[0] = r * std::sin(base + off);
    X[1] = r * std::cos(base - off);
    Y[1] = r * std::sin(base - off);
    return off == 0 ? 1 : 2;
}

} // namespace

GrooveTorchIk GrooveArm::solveTorch(const Vec3& p, const Vec3& tIn) const {
    GrooveTorchIk r;
    const double A1 = g_.a1_mm, D3 = g_.d3_mm, A4 = g_.a4_mm, L = A1 + D3 + A4;
    if (!p.allFinite() || !tIn.allFinite() || !(tIn.norm() > 0)) {
        r.why = "the tip or the torch direction is not a finite vector (or the direction is zero)";
        return r;
    }
    const Vec3 t = tIn.normalized();
    // Reach: o3 runs over the annulus |a1 - d3| .. a1 + d3 of the plane z = 0, the tip is a4
    // from it.
    const double rxy = std::hypot(p.x(), p.y());
    if (std::fabs(p.z()) > A4) {
        r.why =
            formatC("the tip is out of reach: it is %.1f mm %s the plane of links 1 and 2 (base "
                    "z = 0), and the torch link reaches at most a4 = %.0f mm from that plane",
                    std::fabs(p.z()), p.z() > 0 ? "above" : "below", A4);
        return r;
    }
    const double rho = std::sqrt(A4 * A4 - p.z() * p.z());
    const double rIn = std::max(0.0, std::fabs(D3 - A1) - rho), rOut = A1 + D3 + rho;
    if (rxy > rOut + 1e-9 || rxy < rIn - 1e-9) {
        r.why = formatC("the tip is out of reach: it is %.1f mm from joint 1's axis, and at %.1f "
                        "mm from the plane of links 1 and 2 the arm reaches %.1f to %.1f mm from "
                        "that axis (links %.0f and %.0f mm, torch link %.0f mm)",
                        rxy, std::fabs(p.z()), rIn, rOut, A1, D3, A4);
        return r;
    }
    const TorchEq eq{p.x(), p.y(), p.z(),
                     t.x(), t.y(), t.z(),
                     A1,    D3,    0.5 * (p.squaredNorm() + A1 * A1 + D3 * D3 - A4 * A4)};
    const double tz = t.z(), pz = p.z();

    // Joint values at phi for (X, Y) = a1 (c2, s2) and (s3, c3); theta4 and theta5 from the
    // frames.
    auto assemble = [&](double phi, double X, double Y, double s3, double c3) {
        const double cf = std::cos(phi), sf = std::sin(phi);
        const double n2 = std::hypot(X, Y), c2 = X / n2, s2 = Y / n2;
        const double n3 = std::hypot(s3, c3);
        s3 /= n3;
        c3 /= n3;
        const double c1 = cf * c2 + sf * s2, s1 = sf * c2 - cf * s2;
        const Vec3 x3(c3 * cf, c3 * sf, s3), z3(sf, -cf, 0);
        const Vec3 d = p - Vec3(A1 * c1 + D3 * sf, A1 * s1 - D3 * cf, 0);
        const double th4 = std::atan2(-d.dot(z3), d.dot(x3));
        const double c4 = std::cos(th4), s4 = std::sin(th4);
        const Vec3 x4 = c4 * x3 - s4 * z3, y4 = -s4 * x3 - c4 * z3;
        return Q5{std::atan2(s1, c1), std::atan2(s2, c2), std::atan2(s3, c3), th4,
                  std::atan2(t.dot(y4), t.dot(x4))};
    };
    // A candidate: kept when FK reproduces the target (tip < 1e-6 mm, direction < 1e-9),
    // Gauss-Newton first when it is within the gate but not yet at 1e-10 mm / 1e-12. True when
    // the candidate's own solution is in the list: added, or found there when Gauss-Newton
    // stayed near the candidate (a candidate carried to a neighbour already listed does not
    // count: its root's own solution may still be missing).
    double spacing = 1e-7; // distinct solutions (a continuum's sample: 5 deg apart)
    auto consider = [&](Q5 q, double gateMm, double gateDir) {
        const Q5 assembled = q;
        Vec3 pp, tt;
        torch(q, pp, tt);
        double ep = (pp - p).norm(), eo = (tt - t).norm();
        if (!(ep < gateMm && eo < gateDir)) return false;
        if (ep > 1e-10 || eo > 1e-12) {
            polish(nullptr, p, t, q, 12);
            torch(q, pp, tt);
            ep = (pp - p).norm();
            eo = (tt - t).norm();
        }
        if (!(ep < 1e-6 && eo < 1e-9)) return false;
        const size_t before = r.solutions.size();
        addUnique(r.solutions, {wrapped(q), ep + eo}, spacing);
        return r.solutions.size() > before || jointDistance(q, assembled) < 1e-3;
    };
    // Seeds at phi where theta2 solves (iii) alone (the line meets the circle, or nearly) and
    // theta3 solves (i) or (ii) alone. (ii) alone is exact where (i) holds for every theta3 (the
    // torch along z3); both are near the solutions where the roots in phi crowd together.
    auto tipSeeds = [&](double phi, bool fromTorch, bool fromTip, double slack, double gateMm,
                        double gateDir) {
        const TorchEq::At a = eq.at(phi);
        double X[2], Y[2];
        const int n = lineCircle(a.u, a.w, a.K, A1, slack, X, Y);
        bool got = false;
        for (int i = 0; i < n; ++i) {
            const double sc[2][2] = {{tz, a.tau}, {pz, a.u - X[i]}};
            for (int m = 0; m < 2; ++m) {
                if (!(m == 0 ? fromTorch : fromTip)) continue;
                if (!(std::hypot(sc[m][0], sc[m][1]) > (m == 0 ? 1e-9 : 1e-9 * L))) continue;
                for (double sigma : {1.0, -1.0})
                    got |= consider(assemble(phi, X[i], Y[i], sigma * sc[m][0], sigma * sc[m][1]),
                                    gateMm, gateDir);
            }
        }
        return got;
    };

    // P at 9 samples: its 9 Fourier coefficients exactly.
    const TorchTables& tab = torchTables();
    double P[9], pmax = 0, termMax = 0;
    int jmax = 0;
    for (int j = 0; j < 9; ++j) {
        const TorchEq::At a = eq.at(tab.c9[j], tab.s9[j]);
        P[j] = a.P;
        termMax = std::max(termMax, a.terms);
        if (std::fabs(a.P) > pmax) {
            pmax = std::fabs(a.P);
            jmax = j;
        }
    }
    // Within 1e-9 of a horizontal torch with the tip in the plane z = 0 the solutions are
    // those of that singular pose to within rounding: the same continuum.
    const bool horizontalInPlane = std::hypot(tz, pz / A4) < 1e-9;
    if (pmax <= 1e-12 * termMax || horizontalInPlane) {
        // P vanishes for every phi: a continuum of solutions. List a sample of it.
        r.continuum = true;
        spacing = deg2rad(5);
        for (int k = 0; k < 720; ++k)
            tipSeeds(2 * kPi * k / 720, true, true, 0, 1e-3, 1e-6);
        const bool alongAxis = rxy < 1e-9 * L && std::hypot(t.x(), t.y()) < 1e-9;
        r.why = formatC(
            "singular pose: %s; the arm reaches it in a continuum of ways, %zu of them are listed",
            horizontalInPlane
                ? "the torch is horizontal and the tip in the plane of links 1 and 2 (base z = 0), "
                  "so with theta3 = 0 or 180 deg joints 4 and 5 are parallel to joints 1 and 2"
            : alongAxis ? "the tip is on joint 1's axis and the torch along it, so turning joint 1 "
                          "keeps the pose"
                        : "the torch equations hold for every theta1 + theta2",
            r.solutions.size());
        return r;
    }
    double a[5] = {0, 0, 0, 0, 0}, b[5] = {0, 0, 0, 0, 0};
    for (int j = 0; j < 9; ++j) {
        a[0] += P[j] / 9;
        for (int k = 1; k <= 4; ++k) {
            a[k] += 2 * P[j] * tab.c9[(k * j) % 9] / 9;
            b[k] += 2 * P[j] * tab.s9[(k * j) % 9] / 9;
        }
    }
    // phi = phi0 + psi with psi = pi at the largest sample (x = tan(psi / 2) = infinity there,
    // so the polynomial's leading coefficient is that sample: far from 0).
    const double phi0 = 2 * kPi * jmax / 9 - kPi;
    double coef[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int k = 0; k <= 4; ++k) {
        const double ck = std::cos(k * phi0), sk = std::sin(k * phi0);
        const double A = a[k] * ck + b[k] * sk, B = b[k] * ck - a[k] * sk;
        for (int m = 0; m < 9; ++m)
            coef[m] += A * tab.half[k][m].real() + B * tab.half[k][m].imag();
    }
    Eigen::Matrix<double, 8, 8> M = Eigen::Matrix<double, 8, 8>::Zero();
    for (int i = 1; i < 8; ++i)
        M(i, i - 1) = 1;
    for (int j = 0; j < 8; ++j)
        M(0, j) = -coef[7 - j] / coef[8];
    const Eigen::EigenSolver<Eigen::Matrix<double, 8, 8>> es(M, false);
    if (es.info() == Eigen::Success) {
        for (int i = 0; i < 8; ++i) {
            const std::complex<double> z = es.eigenvalues()[i];
            // Real roots, and complex ones close to real (a double root split by rounding).
            if (std::fabs(z.imag()) > 1e-3 * (1 + std::norm(z))) continue;
            double phi = phi0 + 2 * std::atan(z.real());
            for (int it = 0; it < 8; ++it) { // Newton on P, short steps only
                const TorchEq::At e = eq.at(phi);
                const double d = eq.dP(e);
                if (!(std::fabs(d) > 0)) break;
                const double step = e.P / d;
                if (!(std::fabs(step) < 0.05)) break;
                phi -= step;
                if (std::fabs(step) < 1e-15) break;
            }
            const TorchEq::At e = eq.at(phi);
            const double nt = std::hypot(tz, e.tau);
            bool got = false;
            if (std::fabs(tz) > 1e-14 && nt > 1e-14) { // else the torch is along z3: below
                const double X = e.C / tz;
                double Ys[2] = {0, 0};
                int ny = 1;
                if (std::fabs(e.w) > 1e-6 * D3) {
                    Ys[0] = (e.K - e.u * X) / e.w;
                } else { // (iii) does not fix s2: both signs
                    Ys[0] = std::sqrt(std::max(0.0, A1 * A1 - X * X));
                    Ys[1] = -Ys[0];
                    ny = 2;
                }
                for (int i2 = 0; i2 < ny; ++i2)
                    for (double sigma : {1.0, -1.0})
                        got |= consider(assemble(phi, X, Ys[i2], sigma * tz, sigma * e.tau), 1.0,
                                        1e-2);
            }
            // Where the closed form is ill-conditioned (roots crowding together: a torch near
            // horizontal, w near 0, a fold where two solutions meet) seed Gauss-Newton from
            // theta2 of (iii) alone and theta3 of (i) or (ii) alone.
            if (!got) tipSeeds(phi, true, true, 1e-3, 10.0, 0.05);
        }
    }
    // A torch within 1e-3 of horizontal: the roots crowd in pairs round the two phi where the
    // torch is along z3 (for a horizontal torch they are double, and theta3 is fixed by (ii)
    // instead of (i)). Gauss-Newton from the horizontal torch's solutions finds them.
    if (std::fabs(tz) < 1e-3) {
        const double th = std::atan2(t.y(), t.x());
        for (double phi : {th + kPi / 2, th - kPi / 2})
            tipSeeds(phi, false, true, 1e-3, 100.0, 0.1);
    }
    if (r.solutions.empty()) {
        // The tip is within reach (the annulus): the torch direction is not. How far off is the
        // nearest direction the arm can point there (normal to z4 = y3 on the 1-D family of tip
        // solutions)?
        double best = 1e300;
        for (int k = 0; k < 3600; ++k) {
            const double phi = 2 * kPi * k / 3600;
            const TorchEq::At e = eq.at(phi);
            double X[2], Y[2];
            const int n = lineCircle(e.u, e.w, e.K, A1, 0, X, Y);
            for (int i = 0; i < n; ++i) {
                const double s3 = pz, c3 = e.u - X[i], n3 = std::hypot(s3, c3);
                if (!(n3 > 0)) continue;
                const Vec3 z4(-s3 * e.c / n3, -s3 * e.s / n3, c3 / n3);
                best = std::min(best, std::asin(std::min(1.0, std::fabs(z4.dot(t)))));
            }
        }
        if (best < 10) // radians: a direction was found on the sampled family
            r.why = formatC("the torch cannot point along (%.4f, %.4f, %.4f) with the tip at "
                            "(%.4g, %.4g, %.4g) mm (base frame): there it must lie in the plane "
                            "normal to joints 4 and 5, and the nearest direction the arm reaches "
                            "is %.2f deg away",
                            t.x(), t.y(), t.z(), p.x(), p.y(), p.z(), rad2deg(best));
        else // the tip is reached at isolated points only (the edge of the reach)
            r.why = formatC("the torch cannot point along (%.4f, %.4f, %.4f) with the tip at "
                            "(%.4g, %.4g, %.4g) mm (base frame): the tip lies at the edge of the "
                            "arm's reach, where it points the torch in one plane only",
                            t.x(), t.y(), t.z(), p.x(), p.y(), p.z());
    }
    return r;
}

} // namespace cutcell::section_steel
