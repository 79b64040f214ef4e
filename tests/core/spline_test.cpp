// The joint spline is C2 at every knot, interpolates the knots, and starts and ends at rest.
#include "core/trajectory/joint_spline.h"

#include <gtest/gtest.h>

#include <random>

using namespace cutcell;

TEST(Spline, IsC2AtEveryKnotAndInterpolates) {
    std::mt19937 rng(11);
    std::normal_distribution<double> n(0, 1);
    std::vector<JointVector> knots(60);
    JointVector acc = JointVector::Zero();
    for (auto& k : knots) {
        for (int i = 0; i < 6; ++i) // six axes, as the pipe robot's
            acc[i] += n(rng);
        k = acc;
    }
    const double dt = 0.05;
    const JointSpline s(knots, dt);
    for (size_t i = 0; i < knots.size(); ++i) {
        EXPECT_LE((s.evaluate(dt * static_cast<double>(i)).q - knots[i]).cwiseAbs().maxCoeff(),
                  1e-9);
    }
    for (size_t i = 1; i + 1 < knots.size(); ++i) {
        const JointSample left = s.evaluateSegment(i - 1, dt);
        const JointSample right = s.evaluateSegment(i, 0);
        const double scale = 1 + right.qdd.cwiseAbs().maxCoeff();
        EXPECT_LE((left.q - right.q).cwiseAbs().maxCoeff(), 1e-9);
        EXPECT_LE((left.qd - right.qd).cwiseAbs().maxCoeff(), 1e-8 * scale);
        EXPECT_LE((left.qdd - right.qdd).cwiseAbs().maxCoeff(), 1e-7 * scale) << "knot " << i;
    }
    EXPECT_LE(s.evaluateSegment(0, 0).qd.cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LE(s.evaluateSegment(knots.size() - 2, dt).qd.cwiseAbs().maxCoeff(), 1e-9);
}

TEST(Spline, DerivativesAreConsistentWithinASegment) {
    std::vector<JointVector> knots;
    for (int i = 0; i < 10; ++i)
        knots.push_back(JointVector::Constant(std::sin(0.7 * i)));
    const JointSpline s(knots, 0.1);
    const double h = 1e-6;
    for (double t = 0.013; t < 0.85; t += 0.077) {
        const JointSample a = s.evaluate(t - h), b = s.evaluate(t + h), c = s.evaluate(t);
        EXPECT_NEAR((b.q[0] - a.q[0]) / (2 * h), c.qd[0], 1e-5);
        EXPECT_NEAR((b.qd[0] - a.qd[0]) / (2 * h), c.qdd[0], 1e-4);
    }
}

TEST(Spline, ClampsOutsideItsDuration) {
    std::vector<JointVector> knots{JointVector::Zero(), JointVector::Ones(),
                                   JointVector::Constant(3)};
    const JointSpline s(knots, 1.0);
    EXPECT_EQ(s.evaluate(-1).q, knots.front());
    EXPECT_EQ(s.evaluate(5).q, knots.back());
    EXPECT_EQ(s.evaluate(5).qd, JointVector::Zero());
}

// position() is the hot loop's shortcut: it must be evaluate().q exactly, everywhere.
TEST(Spline, PositionIsTheEvaluatedPositionExactly) {
    std::mt19937 rng(3);
    std::normal_distribution<double> n(0, 1);
    std::vector<JointVector> knots(40);
    for (auto& k : knots)
        for (int i = 0; i < kMaxAxes; ++i)
            k[i] = n(rng);
    const JointSpline s(knots, 0.037);
    std::uniform_real_distribution<double> t(-0.1, s.duration() + 0.1);
    for (int k = 0; k < 20000; ++k) {
        const double at = t(rng);
        ASSERT_EQ(s.position(at), s.evaluate(at).q) << "t " << at;
    }
    for (size_t i = 0; i < knots.size(); ++i)
        ASSERT_EQ(s.position(0.037 * static_cast<double>(i)),
                  s.evaluate(0.037 * static_cast<double>(i)).q);
}
