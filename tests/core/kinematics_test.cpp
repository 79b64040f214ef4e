// Forward and inverse kinematics of the seed's arm: round trips on random configurations,
// the seed's closed-form FK, and the status of poses that cannot be reached.
#include "core/job/job.h"
#include "core/machines/pipe_robot/pipe_robot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace cutcell;

namespace {

ArmVector randomInLimits(const PipeRobot& robot, std::mt19937& rng, double margin = 0.02) {
    ArmVector q;
    for (int j = 0; j < kArmJointCount; ++j) {
        std::uniform_real_distribution<double> d(robot.minRad(j + 1) + margin,
                                                 robot.maxRad(j + 1) - margin);
        q[j] = d(rng);
    }
    return q;
}

} // namespace

TEST(Kinematics, ChainMatchesTheSeedsClosedFormPosition) {
    // Seed 000 Eq. (34)-(36), with the columns named n o a (DESIGN.md errata).
    const PipeRobot robot(seedDhTable());
    std::mt19937 rng(1);
    for (int i = 0; i < 500; ++i) {
        const ArmVector q = randomInLimits(robot, rng);
        const double c1 = std::cos(q[0]), s1 = std::sin(q[0]), c2 = std::cos(q[1]),
                     s2 = std::sin(q[1]);
        const double c23 = std::cos(q[1] + q[2]), s23 = std::sin(q[1] + q[2]);
        const double c234 = std::cos(q[1] + q[2] + q[3]), s234 = std::sin(q[1] + q[2] + q[3]);
        const double d1 = 371, a2 = 157, a3 = 120, a4 = 50, d5 = 210;
        const double reach = d5 * s234 + a4 * c234 + a3 * c23 + a2 * c2;
        const Pose T = robot.forward(q);
        EXPECT_NEAR(T.translation().x(), c1 * reach, 1e-9);
        EXPECT_NEAR(T.translation().y(), s1 * reach, 1e-9);
        EXPECT_NEAR(T.translation().z(), -d5 * c234 + a4 * s234 + a3 * s23 + a2 * s2 + d1, 1e-9);
        // Torch axis (third column): o of Eq. (31)-(33).
        EXPECT_NEAR(T.linear()(0, 2), c1 * s234, 1e-12);
        EXPECT_NEAR(T.linear()(1, 2), s1 * s234, 1e-12);
        EXPECT_NEAR(T.linear()(2, 2), -c234, 1e-12);
    }
}

TEST(Kinematics, InverseOfForwardGivesBackTheJoints) {
    const PipeRobot robot(seedDhTable());
    std::mt19937 rng(2);
    // Configurations per IK branch: [tip behind joint 1][elbow down (theta3 < 0)].
    int branch[2][2] = {{0, 0}, {0, 0}};
    for (int i = 0; i < 5000; ++i) {
        const ArmVector q = randomInLimits(robot, rng);
        const Pose T = robot.forward(q);
        // With the true configuration as the continuity reference, IK must return it exactly.
        const IkResult r = robot.solve(T, &q);
        ASSERT_TRUE(r.ok()) << describe(r);
        ASSERT_LE((r.q - q).cwiseAbs().maxCoeff(), 1e-7) << "i = " << i;
        // The tip is behind joint 1 when its reach along the arm's plane is negative.
        const Vec3 armDir(std::cos(q[0]), std::sin(q[0]), 0);
        ++branch[T.translation().dot(armDir) < 0][q[2] < 0];
    }
    // The round trip covers all four branches of the solver (shoulder facing the tip or
    // reaching over backwards, either elbow), so none of them can break unnoticed.
    for (int behind = 0; behind < 2; ++behind)
        for (int down = 0; down < 2; ++down)
            EXPECT_GE(branch[behind][down], 10) << "behind " << behind << ", elbow down " << down;
}

// Every branch `cutcell-cli ik` lists: an "ok" branch reaches the tip and the torch axis, the
// true configuration is among them, and solve() (no reference) returns one of them.
TEST(Kinematics, EveryListedBranchReachesThePose) {
    const PipeRobot robot(seedDhTable());
    std::mt19937 rng(8);
    int okBranches = 0;
    for (int i = 0; i < 2000; ++i) {
        const ArmVector q = randomInLimits(robot, rng);
        const Pose T = robot.forward(q);
        const Vec3 tip = T.translation(), axis = T.linear().col(2);
        const IkBranches all = robot.solveBranches(tip, axis, q[4]);
        ASSERT_GE(all.count, 1);
        ASSERT_LE(all.count, 4);
        bool trueFound = false;
        for (int b = 0; b < all.count; ++b) {
            const IkResult& r = all.branch[static_cast<size_t>(b)];
            if (!r.ok()) {
                EXPECT_FALSE(describe(r).empty());
                continue;
            }
            ++okBranches;
            const Pose Tb = robot.forward(r.q);
            ASSERT_LE((Tb.translation() - tip).norm(), 1e-9) << "i = " << i << " branch " << b;
            ASSERT_LE((Tb.linear().col(2) - axis).norm(), 1e-9) << "i = " << i << " branch " << b;
            for (int j = 0; j < kArmJointCount; ++j)
                ASSERT_TRUE(robot.withinLimits(j + 1, r.q[j])) << "i = " << i << " joint " << j;
            trueFound = trueFound || (r.q - q).cwiseAbs().maxCoeff() < 1e-7;
        }
        EXPECT_TRUE(trueFound) << "i = " << i << " q " << q.transpose();
        const IkResult chosen = robot.solve(tip, axis, q[4]);
        bool listed = false;
        for (int b = 0; b < all.count; ++b)
            listed = listed || all.branch[static_cast<size_t>(b)].q == chosen.q;
        EXPECT_TRUE(listed) << "i = " << i;
    }
    EXPECT_GT(okBranches, 2000); // more than one branch is usually reachable
}

TEST(Kinematics, ForwardOfInverseGivesBackThePose) {
    const PipeRobot robot(seedDhTable());
    std::mt19937 rng(3);
    for (int i = 0; i < 5000; ++i) {
        const Pose T = robot.forward(randomInLimits(robot, rng));
        // Without a reference any in-limit branch may come back; its pose must be the same.
        const IkResult r = robot.solve(T);
        ASSERT_TRUE(r.ok()) << describe(r);
        for (int j = 0; j < kArmJointCount; ++j)
            ASSERT_TRUE(robot.withinLimits(j + 1, r.q[j]));
        const Pose back = robot.forward(r.q);
        ASSERT_LE((back.translation() - T.translation()).norm(), 1e-6);
        ASSERT_LE((back.linear() - T.linear()).cwiseAbs().maxCoeff(), 1e-9);
    }
}

TEST(Kinematics, PositionAndAxisSolveKeepsTheRoll) {
    const PipeRobot robot(seedDhTable());
    std::mt19937 rng(4);
    for (int i = 0; i < 1000; ++i) {
        ArmVector q = randomInLimits(robot, rng);
        const Pose T = robot.forward(q);
        const IkResult r = robot.solve(T.translation(), T.linear().col(2), 0.3, &q);
        ASSERT_TRUE(r.ok()) << describe(r);
        EXPECT_NEAR(r.q[4], 0.3, 1e-12);
        const Pose back = robot.forward(r.q);
        EXPECT_LE((back.translation() - T.translation()).norm(), 1e-6);
        EXPECT_LE((back.linear().col(2) - T.linear().col(2)).norm(), 1e-9);
    }
}

TEST(Kinematics, UnreachablePosesSayWhyNeverWrongAngles) {
    const PipeRobot robot(seedDhTable());
    // Far away: the wrist cannot get there.
    IkResult r = robot.solve(Vec3(900, 0, 300), Vec3(0, 0, -1), 0);
    EXPECT_EQ(r.status, IkStatus::OutOfReach);
    EXPECT_EQ(r.axis, 3);
    EXPECT_GT(r.residual, 100);
    EXPECT_NE(describe(r).find("beyond the arm's reach"), std::string::npos);

    // Torch tilted sideways out of the plane of joint 1: a 5-DOF arm cannot do it.
    const Vec3 sideways = Vec3(0, 0.3, -1).normalized();
    r = robot.solve(Vec3(300, 0, 100), sideways, 0);
    EXPECT_EQ(r.status, IkStatus::OrientationUnreachable);
    EXPECT_NEAR(rad2deg(r.residual), rad2deg(std::asin(0.3 / std::hypot(0.3, 1.0))), 1e-9);

    // Reachable geometrically but only past a joint limit, on every branch: theta2 = 70 deg
    // (limit [-45, 45]); the other elbow needs theta2 = 61.3 deg, the shoulder reaching over
    // backwards needs theta1 = 185.7 deg (limit [-140, 140]).
    ArmVector q;
    q << 0.1, deg2rad(70), deg2rad(-10), deg2rad(10), 0;
    const Pose beyond = robot.forward(q);
    r = robot.solve(beyond, &q);
    ASSERT_EQ(r.status, IkStatus::JointLimit) << describe(r);
    EXPECT_EQ(r.axis, 2);
    EXPECT_NEAR(rad2deg(r.value), 70, 1e-7);
    EXPECT_NEAR(rad2deg(r.limit), 45, 1e-12);
    EXPECT_NEAR(rad2deg(r.residual), 25, 1e-7);
    EXPECT_NE(describe(r).find("joint 2 = 70.000 deg is past its limit 45.000 deg by 25.000 deg"),
              std::string::npos)
        << describe(r);
    // Without a reference the nearest failing branch is reported: still joint 2 past 45 deg.
    r = robot.solve(beyond);
    EXPECT_EQ(r.status, IkStatus::JointLimit) << describe(r);
    EXPECT_EQ(r.axis, 2);
    EXPECT_NEAR(rad2deg(r.limit), 45, 1e-12);
    EXPECT_GT(r.residual, 0);

    // On the joint-1 axis with a vertical torch, theta1 is undefined.
    r = robot.solve(Vec3(0, 0, 100), Vec3(0, 0, -1), 0);
    EXPECT_EQ(r.status, IkStatus::Singular);
    EXPECT_EQ(r.axis, 1);
}

TEST(Kinematics, LimitsUseLowestNotMin) {
    const DhLink unbounded;
    EXPECT_LT(unbounded.min_rad, -1e300);
    EXPECT_GT(unbounded.max_rad, 1e300);
}

TEST(Kinematics, ChuckFrameMapsThePipeAxisOntoX0) {
    const PipeRobot robot(seedDhTable());
    for (double th : {0.0, 0.7, -2.1}) {
        const Pose T = robot.baseFromWork(th);
        EXPECT_NEAR(T.linear().determinant(), 1, 1e-12);
        // Work axis (z) runs along -X0 through (d0, 0, 0).
        EXPECT_LE((T.linear().col(2) - Vec3(-1, 0, 0)).norm(), 1e-12);
        EXPECT_LE((T * Vec3(0, 0, 0) - Vec3(260, 0, 0)).norm(), 1e-12);
    }
    // At theta0 = 0 the work pipe's +y side is on top (Z0 up), seed Eq. (9).
    EXPECT_LE((robot.baseFromWork(0) * Vec3(0, 10, 0) - Vec3(260, 0, 10)).norm(), 1e-12);
}

// The position-only FK (link constants precomputed, no 4x4 algebra) is the full FK's
// translation, on random configurations anywhere in (-2 pi, 2 pi) and on non-seed DH tables.
TEST(Kinematics, TipOnlyForwardEqualsTheFullForwardTranslation) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> angle(-2 * kPi, 2 * kPi), len(-400, 400),
        alpha(-180, 180);
    for (int table = 0; table < 20; ++table) {
        auto dh = seedDhTable();
        if (table > 0)
            for (int i = 1; i < kAxisCount; ++i) {
                auto& r = dh[static_cast<size_t>(i)];
                r.alpha_deg = alpha(rng);
                r.a_mm = len(rng);
                r.d_mm = len(rng);
                r.theta_offset_deg = alpha(rng);
            }
        const PipeRobot robot(dh);
        for (int k = 0; k < 5000; ++k) {
            ArmVector q;
            for (int j = 0; j < kArmJointCount; ++j)
                q[j] = angle(rng);
            const Vec3 full = robot.forward(q).translation();
            const Vec3 tip = robot.tip(q);
            ASSERT_LE((tip - full).cwiseAbs().maxCoeff(), 1e-12 * std::max(1.0, full.norm()))
                << "table " << table << " q " << q.transpose();
            // Two samples at once (the simulation's commanded and actual tips): each lane is
            // tip() of its own sample exactly.
            ArmVector other;
            for (int j = 0; j < kArmJointCount; ++j)
                other[j] = angle(rng);
            Vec3 pairA, pairB;
            robot.tipPair(q, other, pairA, pairB);
            ASSERT_EQ(pairA, tip) << "table " << table << " q " << q.transpose();
            ASSERT_EQ(pairB, robot.tip(other)) << "table " << table << " q " << other.transpose();
        }
    }
}

// The chuck frame inverted as R^T (p - t) is the 4x4 inverse applied to the point.
TEST(Kinematics, WorkFromBaseEqualsTheInverseChuckFrame) {
    auto dh = seedDhTable();
    dh[0].theta_offset_deg = 17;
    const PipeRobot robot(dh);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> angle(-4 * kPi, 4 * kPi), coord(-1000, 1000);
    for (int k = 0; k < 20000; ++k) {
        const double th = angle(rng);
        const Vec3 p(coord(rng), coord(rng), coord(rng));
        const Vec3 viaInverse = robot.baseFromWork(th).inverse() * p;
        const Vec3 viaMatrix = robot.baseFromWork(th).matrix().inverse().topLeftCorner<3, 3>() * p +
                               robot.baseFromWork(th).matrix().inverse().topRightCorner<3, 1>();
        const Vec3 w = robot.workFromBase(th, p);
        ASSERT_LE((w - viaInverse).cwiseAbs().maxCoeff(), 1e-12 * std::max(1.0, p.norm()));
        ASSERT_LE((w - viaMatrix).cwiseAbs().maxCoeff(), 1e-12 * std::max(1.0, p.norm()));
        // And back: the base frame maps it onto p again.
        ASSERT_LE((robot.baseFromWork(th) * w - p).cwiseAbs().maxCoeff(),
                  1e-12 * std::max(1.0, p.norm()));
    }
}
