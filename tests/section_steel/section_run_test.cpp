// The section-steel job through `cutcell-cli run` on the simulated drives (8 PID + plant axes):
// the run completes and its report holds every axis' tracking error, finite and small.
#include "core/json/json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unistd.h>

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
