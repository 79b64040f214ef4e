// Kerf compensation on the profile cutter (issue 24): the torch path is the part edge moved by
// half the kerf toward the scrap side on the pipe surface; the G-code carries it, read back
// through LinuxCNC's own interpreter (rs274) as the G-code export test does.
#include "core/job/job_io.h"
#include "core/machines/profile_cutter/gcode_export.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/profile_kerf.h"
#include "profile_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace cutcell {
namespace {

// A plasma process on the shipped chart with the kerf set by an override (the shipped charts
// give no kerf), the chart row picked at the thickness given.
void setKerf(Job& job, double kerf_mm) {
    test::setPlasmaProcess(job);
    job.process.override.set(CutFigure::KerfMm, kerf_mm);
}

double developedDistance(const ProfileCut& c, const ProfilePoint& a, const ProfilePoint& b) {
    return std::hypot(a.x_mm - b.x_mm, c.work_radius_mm * deg2rad(a.a_deg - b.a_deg));
}

// Distance on the developed surface from q to the nearest segment of the closed polyline.
double distanceToPolyline(const ProfileCut& c, double x, double a_deg) {
    const double R = c.work_radius_mm;
    double best = 1e300;
    for (size_t i = 0; i < c.points.size(); ++i) {
        const ProfilePoint p = c.closedAt(i), q = c.closedAt(i + 1);
        // A wraps on the branch end: take the copy of the point nearest this segment.
        const double turn = c.a_per_turn_deg > 0 ? 360.0 : 0.0;
        double aa = a_deg;
        if (turn > 0) aa += 360.0 * std::round((p.a_deg - a_deg) / 360.0);
        const double ux = q.x_mm - p.x_mm, uy = R * deg2rad(q.a_deg - p.a_deg);
        const double vx = x - p.x_mm, vy = R * deg2rad(aa - p.a_deg);
        const double len2 = ux * ux + uy * uy;
        const double t = len2 > 0 ? std::clamp((vx * ux + vy * uy) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(vx - t * ux, vy - t * uy));
    }
    return best;
}

std::vector<Job> kerfJobs() {
    std::vector<Job> out;
    std::mt19937 rng(2024);
    for (int k = 0; k < 10; ++k) {
        Job job = test::randomProfileJob(rng, k % 2 ? CutTarget::Main : CutTarget::Branch);
        setKerf(job, 0.5 + 1.5 * std::uniform_real_distribution<double>(0, 1)(rng));
        out.push_back(job);
    }
    return out;
}

// The edge comes back from the torch path (the inverse construction) within 1e-6 mm, and every
// torch point lies k/2 from the edge on the surface (to the chords' curvature error).
TEST(ProfileKerf, TheEdgeComesBackFromTheTorchPath) {
    double worstBack = 0, worstGap = 0;
    for (const Job& job : kerfJobs()) {
        const double k = profileKerfMm(job);
        ASSERT_GT(k, 0);
        const ProfileCut edge = computeProfileEdge(job, 720);
        ProfileCut torch = computeProfileCut(job, 720);
        ASSERT_TRUE(torch.kerf_problem.empty()) << torch.kerf_problem;
        ASSERT_EQ(torch.kerf_mm, k);
        for (size_t i = 0; i < torch.points.size(); ++i)
            worstGap = std::max(worstGap, std::fabs(distanceToPolyline(edge, torch.points[i].x_mm,
                                                                       torch.points[i].a_deg) -
                                                    k / 2));
        ASSERT_TRUE(profileEdgeFromTorch(torch).ok());
        for (size_t i = 0; i < edge.points.size(); ++i)
            worstBack =
                std::max(worstBack, developedDistance(edge, edge.points[i], torch.points[i]));
    }
    std::printf("edge from torch path: worst %.3g mm; torch to edge k/2: worst %.3g mm\n",
                worstBack, worstGap);
    EXPECT_LT(worstBack, 1e-6);
    // 720 chords on pipes of radius >= 8 mm: the polyline misses the curve by < 0.01 mm.
    EXPECT_LT(worstGap, 0.01);
}

// The scrap side: the branch end's torch runs beyond the edge (larger X, the off-cut); the
// hole's inside it, so the hole cut with compensation is the edge's size and without it k wider.
TEST(ProfileKerf, TheTorchRunsOnTheScrapSide) {
    for (const Job& job : kerfJobs()) {
        const double k = profileKerfMm(job);
        const ProfileCut edge = computeProfileEdge(job, 720);
        const ProfileCut torch = computeProfileCut(job, 720);
        auto xRange = [](const ProfileCut& c) {
            double lo = 1e300, hi = -1e300;
            for (const auto& p : c.points) {
                lo = std::min(lo, p.x_mm);
                hi = std::max(hi, p.x_mm);
            }
            return std::pair{lo, hi};
        };
        const auto [elo, ehi] = xRange(edge);
        const auto [tlo, thi] = xRange(torch);
        if (job.cut.target == CutTarget::Branch) {
            // Where the edge is furthest out (its X extremes, tangent along A) the torch is k/2
            // further along +X.
            EXPECT_NEAR(thi - ehi, k / 2, 0.01);
            EXPECT_NEAR(tlo - elo, k / 2, 0.01);
        } else {
            // The hole's width along the pipe: the torch's path is k narrower, so the slot's
            // outer face (k/2 outside it) is the edge; without compensation the torch on the
            // edge burns a hole k wider.
            EXPECT_NEAR((ehi - elo) - (thi - tlo), k, 0.01);
        }
    }
}

TEST(ProfileKerf, AKerfTooWideForTheHoleIsRefused) {
    Job job = test::exampleProfileJob();
    job.cut.target = CutTarget::Main;
    setKerf(job, 0.8 * job.branch_pipe.radius_mm);
    const ProfileCut torch = computeProfileCut(job, 360);
    EXPECT_NE(torch.kerf_problem.find("kerf"), std::string::npos) << torch.kerf_problem;
    EXPECT_EQ(torch.kerf_mm, 0);
}

// The G-code's X values are the compensated ones: LinuxCNC's interpreter reads back the torch
// path, not the edge, and the program says so in a comment.
TEST(ProfileKerf, Rs274ReadsBackTheCompensatedPath) {
    int status = 0;
    const std::string rs274 = test::findRs274();
    if (rs274.empty()) GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
    const auto dir =
        std::filesystem::temp_directory_path() / ("cutcell_kerf_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    double worstTorch = 0, leastEdgeGap = 1e300;
    for (size_t j = 0; j < 4; ++j) {
        const Job job = kerfJobs()[j];
        const ProfileCut torch = computeProfileCut(job);
        const ProfileCut edge = computeProfileEdge(job, static_cast<int>(torch.points.size()));
        const std::string g = profileGcode(job, torch);
        EXPECT_NE(g.find("(kerf compensation: X/A below are the torch centre's"),
                  std::string::npos);
        const auto file = dir / ("kerf" + std::to_string(j) + ".ngc");
        writeFileAtomically(file.string(), g);
        const std::string canon = test::runRs274(rs274, file.string(), &status);
        ASSERT_EQ(status, 0) << canon;
        std::istringstream in(canon);
        std::string line;
        std::vector<double> xs;
        while (std::getline(in, line)) {
            const size_t at = line.find("STRAIGHT_FEED(");
            double x = 0;
            if (at != std::string::npos && std::sscanf(line.c_str() + at + 14, "%lf", &x) == 1)
                xs.push_back(x);
        }
        ASSERT_EQ(xs.size(), torch.points.size());
        double edgeHi = -1e300, readHi = -1e300;
        for (size_t i = 0; i < xs.size(); ++i) {
            worstTorch = std::max(worstTorch, std::fabs(xs[i] - torch.closedAt(i + 1).x_mm));
            edgeHi = std::max(edgeHi, edge.points[i].x_mm);
            readHi = std::max(readHi, xs[i]);
        }
        // At the largest X the path runs along A: the read-back X is k/2 off the edge's.
        leastEdgeGap = std::min(leastEdgeGap, std::fabs(readHi - edgeHi) / (torch.kerf_mm / 2));
    }
    std::filesystem::remove_all(dir);
    std::printf("rs274 readback of the compensated path: worst |dX| %.6f mm; edge gap at the X "
                "extreme >= %.4f x k/2\n",
                worstTorch, leastEdgeGap);
    EXPECT_LT(worstTorch, 1e-4 + 1e-9);
    EXPECT_GT(leastEdgeGap, 0.95);
}

} // namespace
} // namespace cutcell
