// The section-steel job through `cutcell-cli run` on the simulated drives (8 PID + plant axes):
// the run completes and its report holds every axis' tracking error, finite and small.
#include "core/json/json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <vector>

TEST(SectionSteelRun, CompletesOnSimulatedDrives) {
    const std::string dir = "/tmp/section_steel_run_" + std::to_string(getpid());
    const std::string cmd = std::string(CUTCELL_CLI) + " run " + CUTCELL_SOURCE_DIR +
                            "/resources/jobs/section_steel_job.json --quiet --runs " + dir +
                            " --report " + dir + "/report.json > /dev/null 2>&1";
    ASSERT_EQ(std::system(("mkdir -p " + dir).c_str()), 0);
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream in(dir + "/report.json");
    std::stringstream ss;
    ss << in.rdbuf();
    const auto doc = cutcell::json::parse(ss.str());
    int axes = 0;
    for (const auto& [k, v] : doc.asObject())
        if (k == "joints")
            for (const auto& j : v.asArray()) {
                ++axes;
                for (const auto& [jk, jv] : j.asObject())
                    if (jk == "max_abs_error_deg") {
                        EXPECT_TRUE(std::isfinite(jv.asNumber()));
                        EXPECT_LT(jv.asNumber(), 0.05); // measured 0.008 deg (path theta3)
                    }
            }
    EXPECT_EQ(axes, 8);
    std::system(("rm -rf " + dir).c_str());
}

namespace {
std::string capture(const std::string& cmd) {
    std::string out;
    FILE* f = popen(cmd.c_str(), "r");
    char buf[4096];
    size_t n;
    while (f && (n = fread(buf, 1, sizeof buf, f)) > 0)
        out.append(buf, n);
    if (f) pclose(f);
    return out;
}
} // namespace

// fk -> ik through the CLI: one branch of ik is the joints fk was given (both arms).
TEST(SectionSteelCli, FkThenIkFindsTheJoints) {
    const std::string job =
        std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/section_steel_job.json";
    struct Case {
        const char* arm;
        std::vector<double> q;
    } cases[] = {{"path", {-60, 90, 60}}, {"groove", {10, 20, 30, 40, 50}}};
    for (const auto& c : cases) {
        std::string joints;
        for (double v : c.q)
            joints += (joints.empty() ? "" : ",") + std::to_string(static_cast<int>(v));
        const auto fk = cutcell::json::parse(capture(std::string(CUTCELL_CLI) + " fk " + job +
                                                     " --arm " + c.arm + " --joints=" + joints));
        std::string pose;
        for (const auto& [k, v] : fk.asObject())
            if (k == "tip_mm" || k == "torch")
                for (const auto& x : v.asArray()) {
                    char b[64];
                    std::snprintf(b, sizeof b, "%.17g", x.asNumber());
                    pose += (pose.empty() ? "" : ",") + std::string(b);
                }
        const auto ik = cutcell::json::parse(capture(std::string(CUTCELL_CLI) + " ik " + job +
                                                     " --arm " + c.arm + " --pose=" + pose));
        bool found = false;
        for (const auto& [k, v] : ik.asObject())
            if (k == "branches")
                for (const auto& b : v.asArray())
                    for (const auto& [bk, bv] : b.asObject())
                        if (bk == "joints_deg") {
                            double d = 0;
                            for (size_t i = 0; i < c.q.size(); ++i)
                                d += std::fabs(bv.asArray()[i].asNumber() - c.q[i]);
                            found |= d < 1e-6;
                        }
        EXPECT_TRUE(found) << c.arm;
    }
    // A machine without arms says so (exit 64).
    const std::string other =
        std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/profile_cutter_job.json";
    EXPECT_NE(
        std::system(
            (std::string(CUTCELL_CLI) + " fk " + other + " --joints 1,2 > /dev/null 2>&1").c_str()),
        0);
}
