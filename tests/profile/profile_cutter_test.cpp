// The profile cutter's trace against the pipes and against the seed's own formulas (Eq. 1, 3, 4).
#include "core/machines/profile_cutter/profile_cutter.h"
#include "profile_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cutcell {
namespace {

constexpr int kJobs = 60;

double branchSurfaceRadius(const Job& job) {
    return job.cut.target == CutTarget::Main ? job.branch_pipe.radius_mm - job.branch_pipe.wall_mm
                                             : job.branch_pipe.radius_mm;
}

TEST(ProfileCutter, TracePointsLieOnBothPipes) {
    std::mt19937 rng(2002);
    for (int k = 0; k < kJobs; ++k) {
        const Job job = test::randomProfileJob(rng, k % 2 ? CutTarget::Main : CutTarget::Branch);
        ASSERT_TRUE(validateJob(job).empty()) << validateJob(job).front().message;
        const ProfileCut cut = computeProfileCut(job, 360);
        const PipeIntersection geom(profileIntersectionSpec(job));
        ASSERT_EQ(cut.points.size(), 360u);
        for (const auto& p : cut.points) {
            EXPECT_LT(geom.mainSurfaceDistance(p.p_main), 1e-9) << "job " << k;
            EXPECT_LT(geom.branchSurfaceDistance(p.p_main), 1e-9) << "job " << k;
            EXPECT_NEAR(std::hypot(p.p_main.x(), p.p_main.y()), job.main_pipe.radius_mm, 1e-9);
        }
        EXPECT_NEAR(geom.spec().branch_radius_mm, branchSurfaceRadius(job), 0);
    }
}

// X and A put the torch over the point: the branch end turns by beta (the point's angle about
// the branch axis) and X + t is constant (the seed's l = L - t); the hole turns the main pipe
// by alpha = atan2(x, y) and X - z is the seed's S.
TEST(ProfileCutter, AxesPlaceTheTorchOverThePoint) {
    std::mt19937 rng(7);
    for (int k = 0; k < kJobs; ++k) {
        const Job job = test::randomProfileJob(rng, k % 2 ? CutTarget::Main : CutTarget::Branch);
        const ProfileCut cut = computeProfileCut(job, 240);
        const PipeIntersection geom(profileIntersectionSpec(job));
        const Vec3 o = geom.branchOrigin(), b = geom.branchAxis(), n = geom.branchY();
        const double ref = job.cut.target == CutTarget::Branch
                               ? cut.points[0].x_mm + (cut.points[0].p_main - o).dot(b)
                               : cut.points[0].x_mm - cut.points[0].p_main.z();
        for (const auto& p : cut.points) {
            if (job.cut.target == CutTarget::Branch) {
                const double t = (p.p_main - o).dot(b);
                EXPECT_NEAR(p.x_mm + t, ref, 1e-9);
                const Vec3 radial = p.p_main - o - t * b;
                const double phi = std::atan2(radial.x(), radial.dot(n));
                EXPECT_NEAR(std::remainder(phi - deg2rad(p.a_deg) - kPi / 2, 2 * kPi), 0, 1e-9);
            } else {
                EXPECT_NEAR(p.x_mm - p.p_main.z(), job.main_pipe.length_mm / 2, 1e-9);
                EXPECT_NEAR(deg2rad(p.a_deg), std::atan2(p.p_main.x(), p.p_main.y()), 1e-12);
            }
        }
        if (job.cut.target == CutTarget::Branch) {
            // The grid's longest X is at most the branch length (the true maximum, off grid).
            EXPECT_LE(std::max_element(cut.points.begin(), cut.points.end(),
                                       [](auto& a, auto& c) { return a.x_mm < c.x_mm; })
                          ->x_mm,
                      job.branch_pipe.length_mm + 1e-9);
        }
    }
}

// The seed's formulas, written out here independently of PipeIntersection:
//   R sin(alpha) = r cos(beta) + e                               (1, front half)
//   l = L - (r sin(beta) cos(theta) + R cos(alpha)) / sin(theta)  (3)
//   s = S + (r sin(beta) + R cos(alpha) cos(theta)) / sin(theta)  (4)
TEST(ProfileCutter, MatchesSeedEquations) {
    std::mt19937 rng(31);
    for (int k = 0; k < kJobs; ++k) {
        const Job job = test::randomProfileJob(rng, k % 2 ? CutTarget::Main : CutTarget::Branch);
        const ProfileCut cut = computeProfileCut(job, 180);
        const double R = job.main_pipe.radius_mm, r = branchSurfaceRadius(job),
                     e = job.eccentricity_mm;
        const double th = deg2rad(job.angle_deg);
        auto alpha = [&](double beta) {
            return std::asin(std::clamp((r * std::cos(beta) + e) / R, -1.0, 1.0));
        };
        auto l = [&](double beta) {
            return -(r * std::sin(beta) * std::cos(th) + R * std::cos(alpha(beta))) / std::sin(th);
        };
        auto s = [&](double beta) {
            return (r * std::sin(beta) + R * std::cos(alpha(beta)) * std::cos(th)) / std::sin(th);
        };
        const double S = job.main_pipe.length_mm / 2;
        const double L = cut.points[0].x_mm - l(0); // the seed's L: where the fixed end is
        for (const auto& p : cut.points) {
            const double beta = deg2rad(p.beta_deg);
            if (job.cut.target == CutTarget::Branch) {
                EXPECT_NEAR(p.x_mm, L + l(beta), 1e-9) << "beta " << p.beta_deg;
                EXPECT_NEAR(p.a_deg, p.beta_deg, 1e-12);
            } else {
                EXPECT_NEAR(p.x_mm, S + s(beta), 1e-9) << "beta " << p.beta_deg;
                EXPECT_NEAR(deg2rad(p.a_deg), alpha(beta), 1e-9) << "beta " << p.beta_deg;
            }
        }
    }
}

TEST(ProfileCutter, ClosedCutIncrementsSumToZero) {
    std::mt19937 rng(5);
    for (int k = 0; k < kJobs; ++k) {
        const Job job = test::randomProfileJob(rng, k % 2 ? CutTarget::Main : CutTarget::Branch);
        const ProfileCut cut = computeProfileCut(job, 400);
        double sum = 0, sumAbs = 0;
        for (double d : cut.increments_x_mm) {
            sum += d;
            sumAbs += std::fabs(d);
        }
        EXPECT_NEAR(sum, 0, 1e-9 * (1 + sumAbs));
        ASSERT_EQ(cut.increments_x_mm.size(), cut.points.size());
        for (size_t i = 0; i < cut.points.size(); ++i)
            EXPECT_NEAR(cut.increments_x_mm[i], cut.closedAt(i + 1).x_mm - cut.points[i].x_mm,
                        1e-12);
    }
}

// X and A of a rotation angle do not depend on the grid, so the NC program, the template and
// the engine's program (each on its own grid) agree.
TEST(ProfileCutter, AxesDoNotDependOnTheGrid) {
    std::mt19937 rng(11);
    std::vector<Job> jobs{test::exampleProfileJob()};
    for (int k = 0; k < 20; ++k)
        jobs.push_back(test::randomProfileJob(rng, k % 2 ? CutTarget::Main : CutTarget::Branch));
    for (const Job& job : jobs) {
        const ProfileCut coarse = computeProfileCut(job, 400), fine = computeProfileCut(job, 4000);
        for (size_t i = 0; i < coarse.points.size(); ++i) {
            EXPECT_NEAR(coarse.points[i].x_mm, fine.points[10 * i].x_mm, 1e-9);
            EXPECT_NEAR(coarse.points[i].a_deg, fine.points[10 * i].a_deg, 1e-9);
        }
        // The longest generatrix is the branch length, to within the grid's sampling.
        double xMax = 0;
        for (const auto& p : fine.points)
            xMax = std::max(xMax, p.x_mm);
        if (job.cut.target == CutTarget::Branch) {
            EXPECT_LE(xMax, job.branch_pipe.length_mm + 1e-9);
            double step = 0; // the grid's sample is within one increment of the true maximum
            for (double d : fine.increments_x_mm)
                step = std::max(step, std::fabs(d));
            EXPECT_GE(xMax, job.branch_pipe.length_mm - step);
        }
    }
}

// The developed length converges as the grid gets finer (a polyline is never longer than the
// curve).
TEST(ProfileCutter, DevelopedLengthConverges) {
    const Job job = test::exampleProfileJob();
    const double coarse = computeProfileCut(job, 200).developedLength();
    const double fine = computeProfileCut(job, 3200).developedLength();
    const double finer = computeProfileCut(job, 12800).developedLength();
    EXPECT_LT(coarse, fine);
    EXPECT_LT(fine, finer);
    EXPECT_LT(finer - fine, fine - coarse);
}

} // namespace
} // namespace cutcell
