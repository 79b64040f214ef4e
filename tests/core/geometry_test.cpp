// The cut curve: every point lies on both pipes, samples are equally spaced in arc length,
// and the torch direction has the bevel asked for.
#include "core/geometry/cut_path.h"
#include "core/job/default_job.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace cutcell;

namespace {

struct Case {
    Job job;
    double branchSurfaceRadius;
};

Job randomJob(std::mt19937& rng, CutTarget target) {
    std::uniform_real_distribution<double> u(0, 1);
    Job job = defaultJob();
    job.main_pipe.radius_mm = 20 + 180 * u(rng);
    job.branch_pipe.radius_mm = 3 + (job.main_pipe.radius_mm - 3) * u(rng);
    job.branch_pipe.wall_mm = 0.5 + 0.3 * job.branch_pipe.radius_mm * u(rng);
    const double room = job.main_pipe.radius_mm - job.branch_pipe.radius_mm;
    job.eccentricity_mm = room * (2 * u(rng) - 1);
    job.angle_deg = 10 + 80 * u(rng);
    job.cut.target = target;
    job.cut.bevel_deg = 40 * u(rng) - 20;
    return job;
}

// Independent of the library: distance from the main cylinder and from the branch cylinder.
double mainDistance(const Job& job, const Vec3& p) {
    return std::fabs(std::hypot(p.x(), p.y()) - job.main_pipe.radius_mm);
}
double branchDistance(const Job& job, const Vec3& p, double radius) {
    const double a = deg2rad(job.angle_deg);
    const Vec3 axis(0, std::sin(a), std::cos(a));
    const Vec3 d = p - Vec3(job.eccentricity_mm, 0, 0);
    return std::fabs((d - d.dot(axis) * axis).norm() - radius);
}

} // namespace

TEST(Geometry, EveryPointLiesOnBothPipesForRandomGeometries) {
    std::mt19937 rng(2024);
    for (int trial = 0; trial < 200; ++trial) {
        const CutTarget target = trial % 2 ? CutTarget::Main : CutTarget::Branch;
        const Job job = randomJob(rng, target);
        const double r = target == CutTarget::Main
                             ? job.branch_pipe.radius_mm - job.branch_pipe.wall_mm
                             : job.branch_pipe.radius_mm;
        const CutGeometry geo(job);
        for (const CutPoint& c : geo.sampleEqualArcLength(geo.length() / 97)) {
            ASSERT_LE(mainDistance(job, c.p_main), 1e-6) << "trial " << trial;
            ASSERT_LE(branchDistance(job, c.p_main, r), 1e-6) << "trial " << trial;
            // The work frame is rigid: the point is on the work pipe's surface there too.
            const double workR =
                target == CutTarget::Main ? job.main_pipe.radius_mm : job.branch_pipe.radius_mm;
            ASSERT_NEAR(std::hypot(c.p_work.x(), c.p_work.y()), workR, 1e-6);
        }
    }
}

TEST(Geometry, TangentEccentricityStillGivesPointsOnBothPipes) {
    Job job = defaultJob();
    job.cut.target = CutTarget::Branch;
    job.eccentricity_mm = job.main_pipe.radius_mm - job.branch_pipe.radius_mm; // |e| + r = R
    const CutGeometry geo(job);
    for (const CutPoint& c : geo.sampleByPhi(360)) {
        EXPECT_LE(mainDistance(job, c.p_main), 1e-6);
        EXPECT_LE(branchDistance(job, c.p_main, job.branch_pipe.radius_mm), 1e-6);
    }
}

TEST(Geometry, SamplesAreEquallySpacedInArcLength) {
    std::mt19937 rng(99);
    for (int trial = 0; trial < 20; ++trial) {
        const Job job = randomJob(rng, trial % 2 ? CutTarget::Main : CutTarget::Branch);
        const CutGeometry geo(job);
        // Reference arc length from a dense polyline over phi, independent of the library's table.
        const int dense = 200000;
        const double phi0 = startPhi(job);
        std::vector<double> cum(dense + 1, 0.0);
        Vec3 prev = geo.curve().point(phi0);
        for (int i = 1; i <= dense; ++i) {
            const Vec3 p = geo.curve().point(phi0 + 2 * kPi * i / dense);
            cum[static_cast<size_t>(i)] = cum[static_cast<size_t>(i) - 1] + (p - prev).norm();
            prev = p;
        }
        EXPECT_NEAR(geo.length(), cum.back(), 1e-6 * cum.back() + 1e-6);
        const auto samples = geo.sampleEqualArcLength(1.0);
        const double step = geo.length() / static_cast<double>(samples.size() - 1);
        for (size_t k = 0; k < samples.size(); ++k) {
            const double u = (samples[k].phi_rad - phi0) / (2 * kPi) * dense;
            const size_t i = std::min<size_t>(static_cast<size_t>(std::max(0.0, u)), dense - 1);
            const double s = cum[i] + (cum[i + 1] - cum[i]) * (u - static_cast<double>(i));
            ASSERT_NEAR(s, step * static_cast<double>(k), 1e-3)
                << "trial " << trial << " sample " << k;
        }
    }
}

TEST(Geometry, TorchDirectionHasTheBevelAndCrossesTheCut) {
    std::mt19937 rng(5);
    for (int trial = 0; trial < 50; ++trial) {
        const Job job = randomJob(rng, trial % 2 ? CutTarget::Main : CutTarget::Branch);
        const CutGeometry geo(job);
        for (const CutPoint& c : geo.sampleByPhi(90)) {
            EXPECT_NEAR(c.approach_work.norm(), 1, 1e-12);
            const double angle =
                rad2deg(std::acos(std::clamp(c.approach_work.dot(c.normal_work), -1.0, 1.0)));
            EXPECT_NEAR(angle, std::fabs(job.cut.bevel_deg), 1e-6);
            // The bevel tilts across the cut, never along it.
            EXPECT_NEAR(c.approach_work.dot(c.tangent_work), 0, 1e-9);
        }
    }
}

TEST(Geometry, NinetyDegreeCentredBranchMatchesTheSeedsClosedForm) {
    // Seed 000 Eq. (6)-(8) for ar = 90 deg, e = 0: x = r sin(phi), y = sqrt(R^2 - x^2), z = -r
    // cos(phi).
    Job job = defaultJob();
    job.cut.target = CutTarget::Branch;
    const CutGeometry geo(job);
    const double R = job.main_pipe.radius_mm, r = job.branch_pipe.radius_mm;
    for (int i = 0; i < 36; ++i) {
        const double phi = 2 * kPi * i / 36;
        const Vec3 p = geo.curve().point(phi);
        EXPECT_NEAR(p.x(), r * std::sin(phi), 1e-9);
        EXPECT_NEAR(p.y(), std::sqrt(R * R - p.x() * p.x()), 1e-9);
        EXPECT_NEAR(p.z(), -r * std::cos(phi), 1e-9);
    }
}
