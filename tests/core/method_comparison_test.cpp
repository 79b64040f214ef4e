// The comparison of the robot's two cutting methods (seed 000, Fig. 11-14): the trace's
// figures are simulateCut's own, the files say the same, and `cutcell-cli compare` writes them
// (and refuses a machine without both methods).
#include "core/job/default_job.h"
#include "core/json/json.h"
#include "core/machines/pipe_robot/cut_simulation.h"
#include "core/machines/pipe_robot/method_comparison.h"
#include "tests/support/run_cli.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace cutcell;
namespace fs = std::filesystem;

namespace {

std::string readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const MethodComparison& defaultComparison() {
    static const MethodComparison c = runMethodComparison(defaultJob());
    return c;
}

} // namespace

TEST(MethodComparison, TheTraceHoldsSimulateCutsOwnFigures) {
    for (const CutMethod m : {CutMethod::StaticPipe, CutMethod::RotatingPipe}) {
        Job job = defaultJob();
        pipeRobotSpec(job).method = m;
        const CutPlan plan = planCut(job);
        ASSERT_TRUE(plan.reachable) << plan.problem;
        const CutTrace t = traceCut(job, plan, 0.01);
        const TrackingReport plain = simulateCut(job, plan);
        EXPECT_EQ(t.cycles, plain.steps);
        for (int i = 0; i < kAxisCount; ++i) {
            const auto a = static_cast<size_t>(i);
            EXPECT_NEAR(t.joint_max_abs_deg[a], t.report.joints[a].max_abs, 1e-12) << i;
            EXPECT_NEAR(t.joint_max_abs_deg[a], plain.joints[a].max_abs, 1e-12) << i;
        }
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(t.tip_min_mm[k], plain.cartesian_min_mm[k], 1e-12) << k;
            EXPECT_NEAR(t.tip_max_mm[k], plain.cartesian_max_mm[k], 1e-12) << k;
        }
        // Every 10 ms from t = 0, the same count in every series.
        EXPECT_NEAR(t.sample_dt_s, 0.01, 1e-12);
        ASSERT_GT(t.t_s.size(), 100u);
        EXPECT_EQ(t.t_s.front(), 0.0);
        EXPECT_NEAR(t.t_s[1] - t.t_s[0], 0.01, 1e-9);
        for (const auto& v : t.joint_error_deg)
            EXPECT_EQ(v.size(), t.t_s.size());
        for (const auto& v : t.tip_error_mm)
            EXPECT_EQ(v.size(), t.t_s.size());
        // Each kept sample lies inside the range taken over every cycle.
        for (size_t s = 0; s < t.t_s.size(); ++s)
            for (int k = 0; k < 3; ++k) {
                EXPECT_GE(t.tip_error_mm[static_cast<size_t>(k)][s], t.tip_min_mm[k]);
                EXPECT_LE(t.tip_error_mm[static_cast<size_t>(k)][s], t.tip_max_mm[k]);
            }
    }
}

TEST(MethodComparison, BothMethodsOfTheDefaultJobAndTheirRatios) {
    const MethodComparison& c = defaultComparison();
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c.staticPipe().method, CutMethod::StaticPipe);
    EXPECT_EQ(c.rotatingPipe().method, CutMethod::RotatingPipe);
    // The static pipe's chuck holds still (seed: "joint 0 is motionless and errorless"): no
    // ratio for it; the arm's joint 2 moves in both methods.
    EXPECT_LT(c.staticPipe().trace.joint_max_abs_deg[0], 1e-9);
    EXPECT_TRUE(std::isnan(c.jointRatio(0)));
    EXPECT_NEAR(c.jointRatio(2),
                c.rotatingPipe().trace.joint_max_abs_deg[2] /
                    c.staticPipe().trace.joint_max_abs_deg[2],
                1e-12);
}

TEST(MethodComparison, JsonMarkdownAndChartsSayTheSame) {
    const MethodComparison& c = defaultComparison();
    const json::Value j = json::parse(json::write(comparisonJson(c)));
    const json::Array& joints = j.find("table")->find("joints")->asArray();
    ASSERT_EQ(joints.size(), static_cast<size_t>(kAxisCount));
    EXPECT_DOUBLE_EQ(joints[3].find("static_pipe_max_abs_deg")->asNumber(),
                     c.staticPipe().trace.joint_max_abs_deg[3]);
    EXPECT_TRUE(joints[0].find("rotating_over_static")->isNull());
    const json::Value& series = *j.find("methods")->find("rotating_pipe")->find("series");
    EXPECT_EQ(series.find("t_s")->asArray().size(), c.rotatingPipe().trace.t_s.size());
    EXPECT_EQ(series.find("joint_error_deg")->asArray().size(), static_cast<size_t>(kAxisCount));

    const std::string md = comparisonMarkdown(c);
    EXPECT_NE(md.find("| joint | static pipe | rotating pipe | rotating / static |"),
              std::string::npos);
    EXPECT_EQ(md.find("-0.000000"), std::string::npos);

    const auto charts = comparisonCharts(c);
    const char* stems[] = {"joint_errors_static", "joint_errors_rotating", "tip_errors_static",
                           "tip_errors_rotating", "max_joint_error"};
    ASSERT_EQ(charts.size(), std::size(stems));
    for (size_t i = 0; i < charts.size(); ++i) {
        EXPECT_EQ(charts[i].first, stems[i]);
        const std::string svg = lineChartSvg(charts[i].second);
        EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
        EXPECT_NE(svg.find("</svg>"), std::string::npos);
        EXPECT_EQ(svg.find("nan"), std::string::npos) << stems[i];
    }
    EXPECT_EQ(charts[0].second.series.size(), static_cast<size_t>(kAxisCount));
    EXPECT_EQ(charts[2].second.series.size(), 3u);
    EXPECT_EQ(charts[4].second.series.size(), 2u);
}

TEST(MethodComparison, CliWritesTheFilesAndRefusesOtherMachines) {
    const fs::path dir = fs::temp_directory_path() / "cutcell_cli_compare";
    fs::remove_all(dir);
    const std::string src = CUTCELL_SOURCE_DIR;
    test::CliResult r =
        test::runCli("compare " + src + "/resources/jobs/default_job.json --out " + dir.string());
    ASSERT_EQ(r.code, 0) << r.output;
    for (const char* f : {"comparison.json", "comparison.md", "joint_errors_static.svg",
                          "joint_errors_rotating.svg", "tip_errors_static.svg",
                          "tip_errors_rotating.svg", "max_joint_error.svg"})
        EXPECT_TRUE(fs::exists(dir / f)) << f;
    const json::Value j = json::parse(readFile(dir / "comparison.json"));
    EXPECT_TRUE(j.find("methods")->find("static_pipe")->find("ok")->asBool());
    EXPECT_EQ(readFile(dir / "joint_errors_static.png").substr(1, 3), "PNG");
    fs::remove_all(dir);

    r = test::runCli("compare " + src + "/resources/jobs/flying_saw_job.json --out " +
                     dir.string());
    EXPECT_EQ(r.code, 64) << r.output;
    EXPECT_NE(r.output.find("static_pipe and rotating_pipe"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir));
}
