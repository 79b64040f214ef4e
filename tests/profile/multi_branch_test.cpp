// Seed 002's several pipes: the set M, its minima N and the increments N'.
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/pipe_joint/multi_branch.h"
#include "profile_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cutcell {
namespace {

// Hand-checkable joint: the cut branch (r = 30) stands at 90 deg on a main pipe R = 100, e = 0,
// so its generatrix phi is the line (r sin phi, t, -r cos phi). A second branch (R2 = 30) leans
// away at 135 deg, its axis through (0, 0, 50) with direction (0, s, c), s = sin 135, c = cos 135.
// The generatrix is at distance R2 from that axis where
//   (r sin phi)^2 + (t c + (r cos phi + 50) s)^2 = R2^2  =>  t = (+-q - (r cos phi + 50) s) / c,
// q = sqrt(R2^2 - r^2 sin^2 phi); a root counts if it lies on the branch's outer half
// ((P - A) . D >= 0) and outside the main pipe. On the main pipe t = sqrt(R^2 - r^2 sin^2 phi).
TEST(MultiBranch, HandCheckableJoint) {
    const double R = 100, r = 30, R2 = 30, pos = 50, L = 500;
    const double a2 = deg2rad(135), s = std::sin(a2), c = std::cos(a2);
    IntersectionSpec spec{R, r, 90, 0, +1};
    const PipeIntersection cut(spec);
    OtherBranch other;
    other.radius_mm = R2;
    other.angle_deg = 135;
    other.position_mm = pos;
    const int n = 720;
    const SetM m = buildSetM(cut, {jointPipeFrom(other)}, L, n, 0.0);
    const ColumnMinima mins = columnMinima(m);
    ASSERT_EQ(m.rows, n);
    ASSERT_EQ(m.cols, 2);
    int mainWins = 0, branchWins = 0;
    for (int i = 0; i < n; ++i) {
        const double phi = 2 * kPi * i / n;
        const double sp = std::sin(phi), cp = std::cos(phi);
        const double tMain = std::sqrt(R * R - r * r * sp * sp);
        EXPECT_NEAR(m.at(i, 0), L - tMain, 1e-9);
        double tOther = -std::numeric_limits<double>::infinity();
        const double q2 = R2 * R2 - r * r * sp * sp;
        if (q2 >= 0)
            for (double sign : {1.0, -1.0}) {
                const double t = (sign * std::sqrt(q2) - (r * cp + pos) * s) / c;
                const double along = t * s + (-r * cp - pos) * c; // (P - A) . D
                const bool outside = r * r * sp * sp + t * t >= R * R - 1e-9;
                if (along >= -1e-9 && outside) tOther = std::max(tOther, t);
            }
        if (std::isfinite(tOther)) {
            EXPECT_NEAR(m.at(i, 1), L - tOther, 1e-9) << "phi " << rad2deg(phi);
        } else {
            EXPECT_TRUE(std::isnan(m.at(i, 1))) << "phi " << rad2deg(phi);
        }
        const double expectN = std::isfinite(tOther) ? std::min(L - tMain, L - tOther) : L - tMain;
        EXPECT_NEAR(mins.N[static_cast<size_t>(i)], expectN, 1e-9);
        (mins.c[static_cast<size_t>(i)] == 0 ? mainWins : branchWins)++;
    }
    // The case is meaningful: each pipe sets part of the cut.
    EXPECT_GT(mainWins, n / 10);
    EXPECT_GT(branchWins, n / 10);
}

bool insideAnyPipe(const Vec3& p, double R, const std::vector<JointPipe>& others, double tol) {
    if (std::hypot(p.x(), p.y()) < R - tol) return true;
    for (const auto& o : others) {
        const Vec3 w = p - o.axis_point;
        const double along = w.dot(o.axis_dir);
        if (along > 0 && (w - along * o.axis_dir).norm() < o.radius_mm - tol) return true;
    }
    return false;
}

// Random joints: N is the row minimum of M, its point lies on the cut branch and on the pipe
// that sets it, and the branch beyond it (toward the fixed end) enters no pipe; N' closes.
TEST(MultiBranch, RandomJointsFitEveryPipe) {
    std::mt19937 rng(4242);
    std::uniform_real_distribution<double> U(0, 1);
    int switches = 0;
    for (int k = 0; k < 40; ++k) {
        const double R = 60 + 100 * U(rng);
        IntersectionSpec spec{R, (0.2 + 0.6 * U(rng)) * R, 30 + 60 * U(rng), 0, +1};
        spec.eccentricity_mm = (2 * U(rng) - 1) * (R - spec.branch_radius_mm);
        const PipeIntersection cut(spec);
        std::vector<JointPipe> others;
        const int count = 1 + static_cast<int>(U(rng) * 3);
        for (int j = 0; j < count; ++j) {
            OtherBranch o;
            o.radius_mm = (0.2 + 0.7 * U(rng)) * R;
            o.eccentricity_mm = (2 * U(rng) - 1) * (R - o.radius_mm);
            o.angle_deg = 30 + 120 * U(rng);
            o.position_mm = (2 * U(rng) - 1) * 2 * R;
            o.phase_deg = (2 * U(rng) - 1) * 60;
            const JointPipe jp = jointPipeFrom(o);
            if (std::fabs(jp.axis_dir.dot(cut.branchAxis())) > std::cos(deg2rad(5))) continue;
            others.push_back(jp);
        }
        const int n = 360;
        const SetM m = buildSetM(cut, others, 1000, n, 0.3);
        const ColumnMinima mins = columnMinima(m);
        double sum = 0;
        for (int i = 0; i < n; ++i) {
            const size_t ui = static_cast<size_t>(i);
            double rowMin = std::numeric_limits<double>::infinity();
            for (int j = 0; j < m.cols; ++j)
                if (std::isfinite(m.at(i, j))) rowMin = std::min(rowMin, m.at(i, j));
            EXPECT_EQ(mins.N[ui], rowMin);
            const int cj = mins.c[ui];
            EXPECT_EQ(m.at(i, cj), rowMin);
            const Vec3 p = m.pointAt(i, cj);
            EXPECT_LT(cut.branchSurfaceDistance(p), 1e-7);
            if (cj == 0) {
                EXPECT_LT(cut.mainSurfaceDistance(p), 1e-7);
            } else {
                const JointPipe& o = others[static_cast<size_t>(cj - 1)];
                const Vec3 w = p - o.axis_point;
                EXPECT_NEAR((w - w.dot(o.axis_dir) * o.axis_dir).norm(), o.radius_mm, 1e-7);
            }
            if (i > 0 && mins.c[ui] != mins.c[ui - 1]) ++switches;
            // Walk from the cut toward the fixed end: the branch wall is in no pipe.
            for (int step = 1; step <= 50; ++step) {
                const Vec3 q = p + cut.branchAxis() * (4.0 * R * step / 50);
                EXPECT_FALSE(insideAnyPipe(q, R, others, 1e-6))
                    << "job " << k << " row " << i << " step " << step;
            }
            sum += mins.N_prime[ui];
        }
        EXPECT_NEAR(sum, 0, 1e-9);
    }
    EXPECT_GT(switches, 0); // some random joints really overlap
}

TEST(MultiBranch, ParallelPipeIsRefused) {
    const PipeIntersection cut(IntersectionSpec{100, 30, 60, 0, +1});
    JointPipe p{Vec3(0, 0, 80), cut.branchAxis(), 20};
    EXPECT_THROW(BranchCrossing(cut, p, 100), std::invalid_argument);
}

// The example job's brace really meets both pipes, and its cut comes from the minima.
TEST(MultiBranch, ExampleJobUsesBothColumns) {
    const Job job = test::exampleProfileJob();
    const ProfileCut cut = computeProfileCut(job);
    int onOther = 0;
    for (const auto& p : cut.points)
        onOther += p.pipe == 1;
    EXPECT_GT(onOther, 0);
    EXPECT_LT(onOther, static_cast<int>(cut.points.size()));
}

} // namespace
} // namespace cutcell
