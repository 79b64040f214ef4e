// Seed 001 kinematics: the printed FK examples of both arms, the erratum of the printed 3R
// inverse, the modified-DH table of the groove arm against every consistently printed element
// of the seed's Eq. (1), and FK -> IK -> FK round trips over random configurations. The groove
// arm's torch IK (tip + direction, every solution): the seed's worked example, 10 000 round
// trips, the count against an independent multistart, horizontal torches, singular poses, the
// reasons for no solution, and `cutcell-cli fk / ik --arm groove`.
#include "core/json/json.h"
#include "core/machines/section_steel/groove_arm.h"
#include "core/machines/section_steel/path_arm.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <sys/wait.h>

using namespace cutcell;
using namespace cutcell::section_steel;

namespace {

double maxPoseError(const Pose& a, const Pose& b) {
    return std::max((a.translation() - b.translation()).norm(),
                    (a.linear() - b.linear()).cwiseAbs().maxCoeff());
}

// The seed's Eq. (1) as printed (first print); only used to show which elements hold.
struct SeedEq1 {
    double nx, ny, nz, ox, oy, oz, ax, ay, az, px, py, pz;
};
SeedEq1 seedEq1(const Q5& q) {
    const double c1 = std::cos(q[0]), s1 = std::sin(q[0]), c2 = std::cos(q[1]), s2 = std::sin(q[1]),
                 c3 = std::cos(q[2]), s3 = std::sin(q[2]), c4 = std::cos(q[3]), s4 = std::sin(q[3]),
                 c5 = std::cos(q[4]), s5 = std::sin(q[4]);
    SeedEq1 e;
    e.nx = -c1 * (s2 * (c4 * s5 + c5 * s4) - c2 * c3 * (c4 * c5 - s4 * s5)) -
           s1 * (c2 * (c4 * s5 + s4 * c5) + c3 * c2 * (c4 * c5 - s5 * s4));
    e.ny = c1 * (c2 * (c4 * s5 + c5 * s4) + s2 * c3 * (c4 * c5 - s4 * s5)) -
           s1 * (s2 * (c4 * s5 + s4 * c5) - c3 * c2 * (c4 * c5 - s5 * s4));
    e.nz = s3 * (c5 * c4 - s5 * s4);
    e.ox = -c1 * (s2 * (c4 * c5 - s5 * s4) + c2 * c3 * (c4 * s5 + s4 * c5)) -
           s1 * (c2 * (c4 * c5 - s4 * s5) - c3 * c2 * (c4 * s5 + c5 * s4));
    e.oy = c1 * (c2 * (c4 * c5 - s5 * s4) - s2 * c3 * (c4 * s5 + s4 * c5)) -
           s1 * (s2 * (c4 * c5 - s4 * s5) + c3 * c2 * (c4 * c5 + c5 * s4));
    e.oz = -s3 * (s5 * c4 + c5 * s4);
    e.ax = s1 * s2 * s3 - c1 * c2 * s3;
    e.ay = s1 * c2 * s3 - c1 * s2 * s3;
    e.az = c3;
    e.px = c1 * (310 * c2 * c3 * c4 - s2 * (310 * s4 - 1110) + 1000) -
           s1 * (c2 * (310 * s4 - 1110) + 310 * c3 * c4 * s2);
    e.py = c1 * (c2 * (310 * s4 - 1110) + 310 * s2 * c3 * c4) +
           s1 * (310 * c2 * c3 * c4 - s2 * (310 * s4 - 1110) + 1000);
    e.pz = 310 * c4 * s3;
    return e;
}

Q5 randomQ(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-kPi, kPi);
    Q5 q;
    for (double& v : q)
        v = u(rng);
    return q;
}

} // namespace

TEST(SectionSteelPathArm, SeedFkExample) {
    // Seed Eq. (6): fkine(r, [pi/2 -pi/4 pi/4]) printed to 4 digits times 1e3.
    const PathArm arm;
    const Pose T = arm.forwardPose({kPi / 2, -kPi / 4, kPi / 4});
    EXPECT_NEAR(T.translation().x(), 784.9, 0.05);
    EXPECT_NEAR(T.translation().y(), 2094.9, 0.05);
    EXPECT_NEAR(T.translation().z(), 0.0, 1e-12);
    Eigen::Matrix3d printed;
    printed << 0, -1, 0, 1, 0, 0, 0, 0, 1;
    EXPECT_LT((T.linear() - printed).cwiseAbs().maxCoeff(), 5e-4);
}

TEST(SectionSteelPathArm, BothBranchesAndThePrintedInverseIsWrong) {
    const PathArm arm;
    const std::array<double, 3> q0{kPi / 2, -kPi / 4, kPi / 4};
    const PlanarPose p = arm.forward(q0);
    const auto sols = arm.inverse(p);
    ASSERT_EQ(sols.size(), 2u);
    bool found = false;
    for (const auto& s : sols) {
        const PlanarPose b = arm.forward(s.q);
        EXPECT_NEAR(b.x_mm, p.x_mm, 1e-9);
        EXPECT_NEAR(b.y_mm, p.y_mm, 1e-9);
        EXPECT_NEAR(wrapAngle(b.phi_rad - p.phi_rad), 0, 1e-12);
        found |= std::fabs(s.q[0] - q0[0]) + std::fabs(s.q[1] - q0[1]) + std::fabs(s.q[2] - q0[2]) <
                 1e-9;
    }
    EXPECT_TRUE(found);
    EXPECT_NE(sols[0].elbow_up, sols[1].elbow_up);
    // The seed's Eq. (7) answer theta = (1.5708, -1.5708, -1.5708) is not a solution: its tip
    // is hundreds of mm away and its torch points the other way.
    const PlanarPose printed = arm.forward({1.5708, -1.5708, -1.5708});
    EXPECT_GT(std::hypot(printed.x_mm - p.x_mm, printed.y_mm - p.y_mm), 100.0);
    EXPECT_GT(std::fabs(wrapAngle(printed.phi_rad - p.phi_rad)), 1.0);
}

TEST(SectionSteelPathArm, RandomRoundTrips) {
    const PathArm arm;
    std::mt19937_64 rng(1);
    double worst = 0;
    for (int k = 0; k < 5000; ++k) {
        const Q5 r = randomQ(rng);
        const std::array<double, 3> q{r[0], r[1], r[2]};
        if (std::fabs(std::sin(q[1])) < 1e-3) continue; // stretched / folded: one branch
        const PlanarPose p = arm.forward(q);
        const auto sols = arm.inverse(p);
        ASSERT_EQ(sols.size(), 2u);
        bool found = false;
        for (const auto& s : sols) {
            const PlanarPose b = arm.forward(s.q);
            worst = std::max(worst, std::hypot(b.x_mm - p.x_mm, b.y_mm - p.y_mm));
            double d = 0;
            for (size_t i = 0; i < 3; ++i)
                d += std::fabs(wrapAngle(s.q[i] - q[i]));
            found |= d < 1e-6;
        }
        EXPECT_TRUE(found);
    }
    EXPECT_LE(worst, 1e-9);
    std::printf("path arm FK->IK->FK worst %.3g mm\n", worst);
}

TEST(SectionSteelGrooveArm, TableReproducesTheConsistentElementsOfEq1) {
    const GrooveArm arm;
    std::mt19937_64 rng(2);
    for (int k = 0; k < 200; ++k) {
        const Q5 q = randomQ(rng);
        const Pose T = arm.forward(q);
        const SeedEq1 e = seedEq1(q);
        const auto& R = T.linear();
        const Vec3 p = T.translation();
        EXPECT_NEAR(R(1, 0), e.ny, 1e-12);
        EXPECT_NEAR(R(2, 0), e.nz, 1e-12);
        EXPECT_NEAR(R(2, 1), e.oz, 1e-12);
        EXPECT_NEAR(R(0, 2), e.ax, 1e-12);
        EXPECT_NEAR(R(2, 2), e.az, 1e-12);
        EXPECT_NEAR(p.x(), e.px, 1e-9);
        EXPECT_NEAR(p.y(), e.py, 1e-9);
        EXPECT_NEAR(p.z(), e.pz, 1e-9);
        EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
        EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    }
}

TEST(SectionSteelGrooveArm, PrintedRotationIsNotARotation) {
    // Erratum: with nx, ny, ox, oy, ay as printed the "rotation" is not orthonormal (at the
    // worked example and in general).
    const Q5 q{kPi / 4, 0, kPi / 2, -kPi / 4, 0};
    const SeedEq1 e = seedEq1(q);
    Eigen::Matrix3d R;
    R << e.nx, e.ox, e.ax, e.ny, e.oy, e.ay, e.nz, e.oz, e.az;
    std::printf("printed Eq. (1) at the example: det = %.6f\n", R.determinant());
    EXPECT_GT(std::fabs(R.determinant() - 1), 0.1);
}

TEST(SectionSteelGrooveArm, SeedWorkedExampleIsAnIkBranch) {
    const GrooveArm arm;
    const Q5 q{kPi / 4, 0, kPi / 2, -kPi / 4, 0};
    const Pose T = arm.forward(q);
    const auto sols = arm.inverse(T);
    ASSERT_FALSE(sols.empty());
    bool found = false;
    for (const auto& s : sols) {
        EXPECT_LE(maxPoseError(arm.forward(s.q), T), 1e-9);
        found |= jointDistance(s.q, q) < 1e-9;
    }
    EXPECT_TRUE(found);
    // The seed's Eq. (5) for theta5 (one sign choice): holds at the example ...
    auto eq5 = [](const Pose& P) {
        const double az = P.linear()(2, 2), oz = P.linear()(2, 1), pz = P.translation().z();
        const double s = std::sqrt(1 - az * az);
        return std::asin(oz / s) - std::acos(pz / (310 * s));
    };
    EXPECT_NEAR(eq5(T), q[4], 1e-9);
    // ... and not at another pose of the arm.
    const Q5 q2{0.3, -0.4, 1.1, 0.5, 0.7};
    EXPECT_GT(std::fabs(eq5(arm.forward(q2)) - q2[4]), 0.1);
}

TEST(SectionSteelGrooveArm, FullPoseRoundTrips) {
    const GrooveArm arm;
    std::mt19937_64 rng(3);
    double worst = 0;
    int tested = 0;
    for (int k = 0; k < 3000; ++k) {
        const Q5 q = randomQ(rng);
        if (std::fabs(std::sin(q[2])) < 0.02) continue; // singular: joints 4/5 parallel to 1/2
        const Pose T = arm.forward(q);
        const auto sols = arm.inverse(T);
        ASSERT_FALSE(sols.empty()) << "k = " << k;
        bool found = false;
        for (const auto& s : sols) {
            worst = std::max(worst, (arm.forward(s.q).translation() - T.translation()).norm());
            EXPECT_LE(maxPoseError(arm.forward(s.q), T), 1e-9);
            found |= jointDistance(s.q, q) < 1e-6;
        }
        EXPECT_TRUE(found) << "k = " << k;
        ++tested;
    }
    EXPECT_LE(worst, 1e-9);
    std::printf("groove arm full pose: %d poses, worst %.3g mm\n", tested, worst);
}

TEST(SectionSteelGrooveArm, TorchRoundTrips) {
    const GrooveArm arm;
    std::mt19937_64 rng(4);
    double worst = 0;
    size_t branches = 0;
    int tested = 0;
    for (int k = 0; k < 400; ++k) {
        const Q5 q = randomQ(rng);
        if (std::fabs(std::sin(q[2])) < 0.05 || std::fabs(std::cos(q[3])) > 0.98) continue;
        const Pose T = arm.forward(q);
        const Vec3 p = T.translation(), t = T.linear().col(0);
        const auto sols = arm.inverseTorch(p, t);
        ASSERT_FALSE(sols.empty()) << "k = " << k;
        bool found = false;
        for (const auto& s : sols) {
            const Pose B = arm.forward(s.q);
            worst = std::max(worst, (B.translation() - p).norm());
            EXPECT_LE((B.translation() - p).norm(), 1e-9);
            EXPECT_LE((B.linear().col(0) - t).norm(), 1e-11);
            found |= jointDistance(s.q, q) < 1e-6;
        }
        EXPECT_TRUE(found) << "k = " << k;
        branches += sols.size();
        ++tested;
    }
    EXPECT_LE(worst, 1e-9);
    std::printf("groove arm torch IK: %d poses, %.2f branches on average, worst %.3g mm\n", tested,
                static_cast<double>(branches) / tested, worst);
}

// ---- Torch IK: every solution (GrooveArm::solveTorch) ----

namespace {

constexpr double kDeg = kPi / 180;

// An independent FK for the checks below: the modified-DH product written out with 4 x 4
// matrices, Rx(alpha) Tx(a) Rz(theta) Tz(d) (not GrooveArm's code).
void mdhFrames(const Q5& q, Eigen::Matrix4d F[6]) {
    const double alpha[5] = {0, 0, kPi / 2, -kPi / 2, 0}, a[5] = {0, 1000, 0, 0, 310},
                 d[5] = {0, 0, 1110, 0, 0};
    F[0] = Eigen::Matrix4d::Identity();
    for (int i = 0; i < 5; ++i) {
        Eigen::Matrix4d Rx = Eigen::Matrix4d::Identity(), Tx = Rx, Rz = Rx, Tz = Rx;
        const double ca = i == 2 || i == 3 ? 0.0 : std::cos(alpha[i]), sa = std::sin(alpha[i]);
        Rx(1, 1) = ca;
        Rx(1, 2) = -sa;
        Rx(2, 1) = sa;
        Rx(2, 2) = ca;
        Tx(0, 3) = a[i];
        const double th = q[static_cast<size_t>(i)];
        Rz(0, 0) = std::cos(th);
        Rz(0, 1) = -std::sin(th);
        Rz(1, 0) = std::sin(th);
        Rz(1, 1) = std::cos(th);
        Tz(2, 3) = d[i];
        F[i + 1] = F[i] * Rx * Tx * Rz * Tz;
    }
}

// Tip and torch errors of q against the target, by the independent FK.
void torchError(const Q5& q, const Vec3& p, const Vec3& t, double& ep, double& et) {
    Eigen::Matrix4d F[6];
    mdhFrames(q, F);
    ep = (F[5].block<3, 1>(0, 3) - p).norm();
    et = (F[5].block<3, 1>(0, 0) - t).norm();
}

// The distinct solutions of the torch target (p, t) that a damped Gauss-Newton (Levenberg-
// Marquardt) on the 5 constraints - tip - p and 500 mm (x5 - t), 6 rows of rank 5 - reaches
// from `starts` random joint vectors (converged: |residual| < 1e-10; distinct: 1e-6 rad).
std::vector<Q5> multistartTorch(const Vec3& p, const Vec3& t, int starts, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-kPi, kPi);
    std::vector<Q5> found;
    constexpr double W = 500;
    using Res = Eigen::Matrix<double, 6, 1>;
    using Jac = Eigen::Matrix<double, 6, 5>;
    auto residual = [&](const Q5& q, Res& r, Jac* J) {
        Eigen::Matrix4d F[6];
        mdhFrames(q, F);
        const Vec3 tip = F[5].block<3, 1>(0, 3), x5 = F[5].block<3, 1>(0, 0);
        r.head<3>() = tip - p;
        r.tail<3>() = W * (x5 - t);
        if (J)
            for (int i = 0; i < 5; ++i) {
                const Vec3 z = F[i + 1].block<3, 1>(0, 2), o = F[i + 1].block<3, 1>(0, 3);
                J->block<3, 1>(0, i) = z.cross(tip - o);
                J->block<3, 1>(3, i) = W * z.cross(x5);
            }
    };
    for (int s = 0; s < starts; ++s) {
        Q5 q;
        for (double& v : q)
            v = u(rng);
        Res r;
        Jac J;
        residual(q, r, &J);
        double cost = r.squaredNorm(), lambda = 1e-3;
        for (int it = 0; it < 200 && cost > 1e-24; ++it) {
            Eigen::Matrix<double, 5, 5> A = J.transpose() * J;
            A.diagonal() += lambda * A.diagonal().cwiseMax(1e-9);
            const Eigen::Matrix<double, 5, 1> dq = -A.ldlt().solve(J.transpose() * r);
            Q5 next = q;
            for (int i = 0; i < 5; ++i)
                next[static_cast<size_t>(i)] += dq[i];
            Res rn;
            residual(next, rn, nullptr);
            if (rn.squaredNorm() < cost) {
                q = next;
                lambda = std::max(lambda * 0.2, 1e-12);
                residual(q, r, &J);
                cost = r.squaredNorm();
            } else if ((lambda *= 10) > 1e12) {
                break;
            }
        }
        if (cost > 1e-20) continue;
        for (double& v : q)
            v = wrapAngle(v);
        bool known = false;
        for (const Q5& o : found)
            known |= jointDistance(o, q) < 1e-6;
        if (!known) found.push_back(q);
    }
    return found;
}

bool among(const std::vector<GrooveArmSolution>& sols, const Q5& q, double tol = 1e-6) {
    for (const auto& s : sols)
        if (jointDistance(s.q, q) < tol) return true;
    return false;
}

Q5 deg(double a, double b, double c, double d, double e) {
    return {a * kDeg, b * kDeg, c * kDeg, d * kDeg, e * kDeg};
}

std::string text(const Q5& q) {
    char b[160];
    std::snprintf(b, sizeof b, "(%.9f, %.9f, %.9f, %.9f, %.9f) deg", q[0] / kDeg, q[1] / kDeg,
                  q[2] / kDeg, q[3] / kDeg, q[4] / kDeg);
    return b;
}

} // namespace

TEST(SectionSteelGrooveArm, SeedWorkedExampleFkInTheBaseFrame) {
    // The seed's groove-arm example q = [pi/4 0 pi/2 -pi/4 0] (base frame {0}): frame 2 at
    // 1000 mm along 45 deg, link 2 (1110 mm) along z3 = (s45, -c45, 0), the torch link
    // (310 mm) along x4 = c4 x3 - s4 z3 with x3 = z0.
    const GrooveArm arm;
    const Q5 q = deg(45, 0, 90, -45, 0);
    const Pose T = arm.forward(q);
    const double h = std::sqrt(0.5);
    const Vec3 p((1000 + 1110) * h + 310 * 0.5, (1000 - 1110) * h - 310 * 0.5, 310 * h);
    EXPECT_LT((T.translation() - p).norm(), 1e-9);
    EXPECT_LT((T.linear().col(0) - Vec3(0.5, -0.5, h)).norm(), 1e-12); // n: the torch
    EXPECT_LT((T.linear().col(1) - Vec3(-0.5, 0.5, h)).norm(), 1e-12); // o
    EXPECT_LT((T.linear().col(2) - Vec3(-h, -h, 0)).norm(), 1e-12);    // a: joints 4, 5
    // The seed's Eq. (1) position as printed: p_x, p_y, p_z (consistent in both prints).
    const SeedEq1 e = seedEq1(q);
    EXPECT_LT((Vec3(e.px, e.py, e.pz) - p).norm(), 1e-9);
    // The closed-form torch FK agrees with the frames.
    Vec3 tp, tt;
    arm.torch(q, tp, tt);
    EXPECT_LT((tp - p).norm(), 1e-9);
    EXPECT_LT((tt - T.linear().col(0)).norm(), 1e-12);
}

TEST(SectionSteelGrooveArm, SeedWorkedExampleTorchIkHasBothWrists) {
    // The seed's IK answer (ikine and its model, printed to 4 decimals): theta = (0.7854, 0,
    // 1.5708, -0.7854, 0) for the torch of its example. With the roll free the torch target
    // has 8 solutions; the seed's q and its wrist-flipped twin (45, 0, -90, -135, 0) deg are two.
    const GrooveArm arm;
    const Q5 q = deg(45, 0, 90, -45, 0);
    const Pose T = arm.forward(q);
    const Vec3 p = T.translation(), t = T.linear().col(0);
    const GrooveTorchIk ik = arm.solveTorch(p, t);
    EXPECT_TRUE(ik.why.empty()) << ik.why;
    EXPECT_FALSE(ik.continuum);
    ASSERT_EQ(ik.solutions.size(), 8u);
    for (const auto& s : ik.solutions) {
        double ep = 0, et = 0;
        torchError(s.q, p, t, ep, et);
        EXPECT_LT(ep, 1e-9) << text(s.q);
        EXPECT_LT(et, 1e-11) << text(s.q);
    }
    EXPECT_TRUE(among(ik.solutions, q));
    EXPECT_TRUE(among(ik.solutions, deg(45, 0, -90, -135, 0)));
    EXPECT_TRUE(among(ik.solutions, {0.7854, 0, 1.5708, -0.7854, 0}, 1e-4)); // as printed
    std::mt19937_64 rng(21);
    const auto ms = multistartTorch(p, t, 300, rng);
    EXPECT_EQ(ms.size(), ik.solutions.size());
    for (const Q5& m : ms)
        EXPECT_TRUE(among(ik.solutions, m)) << text(m);
    // A pose where the former 1-D root search found nothing: 4 solutions, q among them.
    const Q5 q2 = deg(161.719, 40.321, -96.805, -25.595, -49.532);
    const Pose T2 = arm.forward(q2);
    const GrooveTorchIk ik2 = arm.solveTorch(T2.translation(), T2.linear().col(0));
    EXPECT_EQ(ik2.solutions.size(), 4u);
    EXPECT_TRUE(among(ik2.solutions, q2));
}

TEST(SectionSteelGrooveArm, TorchIkRoundTrips10000) {
    // FK(IK(x)) = x on 10 000 poses from FK of random q in (-pi, pi]^5: every solution
    // reproduces the pose (independent FK) and the generating q is among them. Degenerate
    // poses (a continuum of solutions: the torch horizontal and the tip in the plane z = 0 to
    // within 1e-9, or tip and torch on joint 1's axis) would be counted apart: none occur.
    const GrooveArm arm;
    std::mt19937_64 rng(6);
    double worstP = 0, worstT = 0;
    size_t total = 0;
    int continua = 0, histogram[17] = {};
    for (int k = 0; k < 10000; ++k) {
        const Q5 q = randomQ(rng);
        const Pose T = arm.forward(q);
        const Vec3 p = T.translation(), t = T.linear().col(0);
        const GrooveTorchIk ik = arm.solveTorch(p, t);
        if (ik.continuum) {
            ++continua;
            continue;
        }
        EXPECT_TRUE(ik.why.empty()) << "k = " << k << ": " << ik.why;
        for (const auto& s : ik.solutions) {
            double ep = 0, et = 0;
            torchError(s.q, p, t, ep, et);
            worstP = std::max(worstP, ep);
            worstT = std::max(worstT, et);
        }
        EXPECT_TRUE(among(ik.solutions, q)) << "k = " << k << " q = " << text(q);
        total += ik.solutions.size();
        ++histogram[std::min<size_t>(ik.solutions.size(), 16)];
    }
    EXPECT_EQ(continua, 0);
    EXPECT_LE(worstP, 1e-9);
    EXPECT_LE(worstT, 1e-13); // measured 9.3e-16
    std::printf("groove torch IK round trips: 10000 poses, %zu solutions (%.3f per pose), worst "
                "%.3g mm / %.3g; solutions per pose:",
                total, static_cast<double>(total) / 10000, worstP, worstT);
    for (int n = 0; n <= 16; ++n)
        if (histogram[n]) std::printf(" %d x%d", n, histogram[n]);
    std::printf("\n");
}

TEST(SectionSteelGrooveArm, TorchIkCountMatchesAMultistart) {
    // Completeness: on 1000 random reachable poses the solutions equal those an independent
    // multistart finds (300 random starts of Levenberg-Marquardt, mdhFrames above). Every
    // multistart solution must be an IK solution (none missed). The multistart may miss one
    // whose basin its 300 starts do not hit (near theta3 = 0 or 180 deg, where joints 4/5 are
    // nearly parallel to 1/2): those poses are printed with the IK's extra solution, which the
    // independent FK checks; a handful at most.
    const GrooveArm arm;
    std::mt19937_64 rng(7), starts(8);
    int equal = 0, msFewer = 0, missed = 0;
    size_t ikTotal = 0;
    for (int k = 0; k < 1000; ++k) {
        const Q5 q = randomQ(rng);
        const Pose T = arm.forward(q);
        const Vec3 p = T.translation(), t = T.linear().col(0);
        const GrooveTorchIk ik = arm.solveTorch(p, t);
        const std::vector<Q5> ms = multistartTorch(p, t, 300, starts);
        ikTotal += ik.solutions.size();
        for (const Q5& m : ms)
            if (!among(ik.solutions, m)) {
                ++missed;
                ADD_FAILURE() << "k = " << k << ": the IK misses " << text(m);
            }
        if (ms.size() == ik.solutions.size()) {
            ++equal;
            continue;
        }
        if (ms.size() < ik.solutions.size()) ++msFewer;
        std::printf("pose %d (q = %s): IK %zu solutions, multistart %zu\n", k, text(q).c_str(),
                    ik.solutions.size(), ms.size());
        for (const auto& s : ik.solutions) {
            bool inMs = false;
            for (const Q5& m : ms)
                inMs |= jointDistance(s.q, m) < 1e-6;
            if (inMs) continue;
            double ep = 0, et = 0;
            torchError(s.q, p, t, ep, et);
            std::printf("  IK only: %s, FK error %.2g mm / %.2g\n", text(s.q).c_str(), ep, et);
            EXPECT_LT(ep, 1e-9);
            EXPECT_LT(et, 1e-11);
        }
    }
    EXPECT_EQ(missed, 0);
    EXPECT_GE(equal, 995);
    EXPECT_EQ(equal + msFewer, 1000);
    std::printf("groove torch IK vs multistart: 1000 poses, %zu IK solutions, equal counts on %d, "
                "multistart short on %d, IK short on %d\n",
                ikTotal, equal, msFewer, 1000 - equal - msFewer);
}

TEST(SectionSteelGrooveArm, TorchIkHorizontalTorch) {
    // A horizontal torch (n_z = s3 c45 = 0 with theta5 = 90 deg - theta4): theta1 + theta2 is
    // fixed by the torch (it lies along z3), the polynomial's roots are double; and a torch
    // 1e-9 .. 1e-3 off horizontal, where they crowd together in pairs. The generating q is
    // found every time.
    const GrooveArm arm;
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> e10(-9, -3);
    int found = 0, tested = 0;
    for (int k = 0; k < 4000; ++k) {
        Q5 q = randomQ(rng);
        q[4] = kPi / 2 - q[3];
        if (k % 2) q[4] += (k % 4 == 1 ? 1 : -1) * std::pow(10.0, e10(rng));
        if (std::fabs(std::sin(q[2])) < 1e-3) continue; // the continuum: below
        const Pose T = arm.forward(q);
        const Vec3 p = T.translation(), t = T.linear().col(0);
        const GrooveTorchIk ik = arm.solveTorch(p, t);
        for (const auto& s : ik.solutions) {
            double ep = 0, et = 0;
            torchError(s.q, p, t, ep, et);
            EXPECT_LT(ep, 1e-6);
            EXPECT_LT(et, 1e-9);
        }
        const bool in = among(ik.solutions, q);
        EXPECT_TRUE(in) << "k = " << k << " q = " << text(q) << " n_z = " << t.z();
        found += in ? 1 : 0;
        ++tested;
    }
    std::printf("groove torch IK, horizontal torch (+- 1e-9 .. 1e-3): %d of %d found\n", found,
                tested);
}

TEST(SectionSteelGrooveArm, TorchIkSingularPosesAreAContinuum) {
    const GrooveArm arm;
    // Torch horizontal, tip in the plane z = 0 (theta3 = 0: joints 4, 5 parallel to 1, 2): a
    // planar 3R arm with a free wrist, a continuum. A sample is listed, with the reason.
    for (const Q5& q : {Q5{0.3, 0.4, 0, 0.5, 1.0}, Q5{-1.2, 2.0, kPi, -0.7, 0.2}}) {
        const Pose T = arm.forward(q);
        const Vec3 p = T.translation(), t = T.linear().col(0);
        const GrooveTorchIk ik = arm.solveTorch(p, t);
        EXPECT_TRUE(ik.continuum);
        EXPECT_NE(ik.why.find("singular pose: the torch is horizontal and the tip in the plane"),
                  std::string::npos)
            << ik.why;
        EXPECT_GT(ik.solutions.size(), 10u);
        for (const auto& s : ik.solutions) {
            double ep = 0, et = 0;
            torchError(s.q, p, t, ep, et);
            EXPECT_LT(ep, 1e-6);
            EXPECT_LT(et, 1e-9);
        }
    }
    // Tip on joint 1's axis, torch along it: turning joint 1 keeps the pose.
    const double z = std::sqrt(310.0 * 310.0 - 110.0 * 110.0);
    const GrooveTorchIk axis = arm.solveTorch(Vec3(0, 0, z), Vec3(0, 0, 1));
    EXPECT_TRUE(axis.continuum);
    EXPECT_NE(axis.why.find("on joint 1's axis"), std::string::npos) << axis.why;
    EXPECT_FALSE(axis.solutions.empty());
    for (const auto& s : axis.solutions) {
        double ep = 0, et = 0;
        torchError(s.q, Vec3(0, 0, z), Vec3(0, 0, 1), ep, et);
        EXPECT_LT(ep, 1e-6);
        EXPECT_LT(et, 1e-9);
    }
}

TEST(SectionSteelGrooveArm, TorchIkOutOfReachSaysWhy) {
    const GrooveArm arm;
    struct Case {
        Vec3 p, t;
        const char* words[2];
    } cases[] = {
        // Beyond the outer radius a1 + d3 + sqrt(a4^2 - z^2).
        {{3000, 0, 0}, {0, 0, 1}, {"3000.0 mm from joint 1's axis", "reaches 0.0 to 2420.0 mm"}},
        // Inside the hole: |d3 - a1| - sqrt(310^2 - 300^2) = 31.9 mm.
        {{10, 0, 300}, {0, 0, 1}, {"10.0 mm from joint 1's axis", "reaches 31.9 to 2188.1 mm"}},
        // Higher than the torch link reaches from the links' plane.
        {{1000, 0, 400}, {1, 0, 0}, {"400.0 mm above the plane", "a4 = 310 mm"}},
        // In reach, but the torch cannot point that way there.
        {{50, 0, 20}, {0, 0, 1}, {"the torch cannot point along", "85.29 deg away"}},
        // At the edge of the reach (|z| = a4): the tip's solutions are isolated points, no
        // direction is sampled there - the reason says so instead of printing "1e300 deg away".
        {{1500, 0, 310}, {0, 1, 0}, {"the torch cannot point along", "edge of the arm's reach"}},
    };
    for (const auto& c : cases) {
        const GrooveTorchIk ik = arm.solveTorch(c.p, c.t);
        EXPECT_TRUE(ik.solutions.empty());
        EXPECT_TRUE(arm.inverseTorch(c.p, c.t).empty());
        for (const char* w : c.words)
            EXPECT_NE(ik.why.find(w), std::string::npos) << ik.why;
    }
}

namespace {
struct CliRun {
    int code = -1;
    std::string out;
};
CliRun cli(const std::string& args) {
    CliRun r;
    FILE* f = popen((std::string(CUTCELL_CLI) + " " + args + " 2>/dev/null").c_str(), "r");
    char buf[4096];
    size_t n;
    while (f && (n = fread(buf, 1, sizeof buf, f)) > 0)
        r.out.append(buf, n);
    if (f) {
        const int st = pclose(f);
        r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    }
    return r;
}
std::vector<double> numbers(const json::Value* v) {
    std::vector<double> out;
    if (v)
        for (const auto& x : v->asArray())
            out.push_back(x.asNumber());
    return out;
}
} // namespace

TEST(SectionSteelGrooveArm, CliIkListsEveryBranchOrSaysWhyNot) {
    const std::string job =
        std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/section_steel_job.json";
    // fk: the whole torch frame, in the cell and in the arm's base frame.
    const CliRun fk = cli("fk " + job + " --arm groove --joints 45,0,90,-45,0");
    ASSERT_EQ(fk.code, 0) << fk.out;
    const json::Value f = json::parse(fk.out);
    const std::vector<double> tip = numbers(f.find("tip_mm")), torch = numbers(f.find("torch"));
    ASSERT_EQ(tip.size(), 3u);
    EXPECT_EQ(numbers(f.find("x_axis")), torch);
    EXPECT_EQ(numbers(f.find("y_axis")).size(), 3u);
    EXPECT_EQ(numbers(f.find("z_axis")).size(), 3u);
    const json::Value* base = f.find("base");
    ASSERT_NE(base, nullptr);
    const GrooveArm arm;
    const Pose T = arm.forward(deg(45, 0, 90, -45, 0));
    const std::vector<double> btip = numbers(base->find("tip_mm")),
                              bx = numbers(base->find("x_axis")),
                              by = numbers(base->find("y_axis")),
                              bz = numbers(base->find("z_axis"));
    ASSERT_EQ(btip.size(), 3u);
    ASSERT_EQ(bz.size(), 3u);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(btip[static_cast<size_t>(i)], T.translation()[i], 1e-9);
        EXPECT_NEAR(bx[static_cast<size_t>(i)], T.linear()(i, 0), 1e-12);
        EXPECT_NEAR(by[static_cast<size_t>(i)], T.linear()(i, 1), 1e-12);
        EXPECT_NEAR(bz[static_cast<size_t>(i)], T.linear()(i, 2), 1e-12);
    }
    // ik at the seed's torch in the cell frame: both wrists of the seed's q among 8 branches.
    const CliRun ik = cli("ik " + job +
                          " --arm groove --pose=-219.20310216782974,-667.2182540694796,"
                          "-446.9953083036153,-0.7071067811865476,0.5,-0.5");
    ASSERT_EQ(ik.code, 0) << ik.out;
    const json::Value i = json::parse(ik.out);
    EXPECT_EQ(i.find("status")->asString(), "ok");
    EXPECT_EQ(i.find("reason"), nullptr);
    const auto& branches = i.find("branches")->asArray();
    EXPECT_EQ(branches.size(), 8u);
    for (const Q5& want : {deg(45, 0, 90, -45, 0), deg(45, 0, -90, -135, 0)}) {
        bool found = false;
        for (const auto& b : branches) {
            const std::vector<double> j = numbers(b.find("joints_deg"));
            Q5 q{};
            for (size_t k = 0; k < 5; ++k)
                q[k] = j[k] * kDeg;
            found |= jointDistance(q, want) < 1e-8;
        }
        EXPECT_TRUE(found) << text(want) << "\n" << ik.out;
    }
    // Out of reach: the JSON says why (status, reason), exit 3 as an unreachable plan.
    const CliRun far = cli("ik " + job + " --arm groove --pose 0,-900,4000,1,0,0");
    EXPECT_EQ(far.code, 3) << far.out;
    const json::Value v = json::parse(far.out);
    EXPECT_EQ(v.find("status")->asString(), "unreachable");
    EXPECT_NE(v.find("reason")->asString().find("mm from joint 1's axis"), std::string::npos)
        << far.out;
    EXPECT_TRUE(v.find("branches")->asArray().empty());
}
