// LinuxCNC G-code of the profile cutter, read back through LinuxCNC's own interpreter (rs274,
// from Debian's linuxcnc-uspace); skipped where rs274 is not installed.
#include "core/job/job_io.h"
#include "core/machines/profile_cutter/gcode_export.h"
#include "profile_test_util.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace cutcell {
namespace {

std::vector<Job> jobs() {
    std::vector<Job> out{test::exampleProfileJob()};
    std::mt19937 rng(1234);
    for (int k = 0; k < 8; ++k)
        out.push_back(test::randomProfileJob(rng, k % 2 ? CutTarget::Main : CutTarget::Branch));
    Job hole = test::exampleProfileJob();
    hole.cut.target = CutTarget::Main;
    out.push_back(hole);
    return out;
}

struct Move {
    double x, a, f;
};

// The G1 blocks as written (X, A, F).
std::vector<Move> writtenMoves(const std::string& g) {
    std::vector<Move> out;
    std::istringstream in(g);
    std::string line;
    Move m{};
    while (std::getline(in, line))
        if (std::sscanf(line.c_str(), "G1 X%lf A%lf F%lf", &m.x, &m.a, &m.f) == 3) out.push_back(m);
    return out;
}

// The four first coordinates (X, Y, Z, A) of a canonical call such as
// "   20 N..... STRAIGHT_FEED(10.5000, 0.0000, 0.0000, 10.0000, 0.0000, 0.0000)".
bool canonCall(const std::string& line, const std::string& name, double* x, double* a) {
    const size_t at = line.find(name + "(");
    double y = 0, z = 0;
    return at != std::string::npos && std::sscanf(line.c_str() + at + name.size() + 1,
                                                  "%lf, %lf, %lf, %lf", x, &y, &z, a) == 4;
}

// Inverse-time feed: every move takes ds / v on the developed surface.
TEST(GcodeExport, FeedKeepsTheSurfaceSpeed) {
    for (const Job& job : jobs()) {
        const ProfileCut cut = computeProfileCut(job);
        GcodeStats st;
        const std::string g = profileGcode(job, cut, &st);
        const auto moves = writtenMoves(g);
        ASSERT_EQ(moves.size(), st.moves);
        ASSERT_EQ(moves.size(), cut.points.size());
        double px = std::round(cut.points[0].x_mm * 1e4) / 1e4,
               pa = std::round(cut.points[0].a_deg * 1e4) / 1e4;
        for (const Move& m : moves) {
            const double ds = std::hypot(m.x - px, cut.work_radius_mm * deg2rad(m.a - pa));
            const double minutes = 1.0 / m.f;
            EXPECT_NEAR(ds / (minutes * 60), job.cut.speed_mm_s, 1e-4 * job.cut.speed_mm_s);
            px = m.x;
            pa = m.a;
        }
        EXPECT_NEAR(st.time_s * job.cut.speed_mm_s, st.length_mm, 1e-6 * st.length_mm);
        EXPECT_NE(g.find("G93"), std::string::npos);
        EXPECT_NE(g.find("M3"), std::string::npos);
        EXPECT_NE(g.find("M5"), std::string::npos);
    }
}

TEST(GcodeExport, CommentsCannotBreakTheProgram) {
    Job job = test::exampleProfileJob();
    job.name = "tee (DN80) on (DN150)\nsecond line";
    const std::string g = profileGcode(job, computeProfileCut(job));
    EXPECT_NE(g.find("(job: tee [DN80] on [DN150] second line)"), std::string::npos);
}

// rs274 accepts the program and its canonical moves are the cut's X/A points.
TEST(GcodeExport, Rs274ReadsBackTheSamePoints) {
    const std::string rs274 = test::findRs274();
    if (rs274.empty()) GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
    const auto dir =
        std::filesystem::temp_directory_path() / ("cutcell_gcode_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    double worstX = 0, worstA = 0;
    for (size_t k = 0; k < jobs().size(); ++k) {
        const Job job = jobs()[k];
        const ProfileCut cut = computeProfileCut(job);
        const auto file = dir / ("job" + std::to_string(k) + ".ngc");
        writeFileAtomically(file.string(), profileGcode(job, cut));
        int status = 0;
        const std::string canon = test::runRs274(rs274, file.string(), &status);
        ASSERT_EQ(status, 0) << canon;
        std::vector<std::pair<double, double>> feeds;
        std::istringstream in(canon);
        std::string line;
        bool torchOn = false, torchOff = false, sawTraverse = false;
        double x = 0, a = 0;
        while (std::getline(in, line)) {
            if (canonCall(line, "STRAIGHT_TRAVERSE", &x, &a)) {
                sawTraverse = true;
                EXPECT_NEAR(x, cut.points[0].x_mm, 0.01);
                EXPECT_NEAR(a, cut.points[0].a_deg, 0.01);
            }
            if (line.find("START_SPINDLE_CLOCKWISE") != std::string::npos) torchOn = true;
            if (canonCall(line, "STRAIGHT_FEED", &x, &a)) {
                EXPECT_TRUE(torchOn) << "cut move before torch on";
                feeds.emplace_back(x, a);
            }
            if (line.find("STOP_SPINDLE_TURNING") != std::string::npos && !feeds.empty())
                torchOff = true;
        }
        EXPECT_TRUE(sawTraverse && torchOn && torchOff);
        ASSERT_EQ(feeds.size(), cut.points.size());
        for (size_t i = 0; i < feeds.size(); ++i) {
            const ProfilePoint p = cut.closedAt(i + 1);
            worstX = std::max(worstX, std::fabs(feeds[i].first - p.x_mm));
            worstA = std::max(worstA, std::fabs(feeds[i].second - p.a_deg));
        }
    }
    std::filesystem::remove_all(dir);
    EXPECT_LT(worstX, 0.01);
    EXPECT_LT(worstA, 0.01);
    std::printf("rs274 readback: worst |dX| = %.6f mm, worst |dA| = %.6f deg\n", worstX, worstA);
}

} // namespace
} // namespace cutcell
