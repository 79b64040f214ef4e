// End to end: `cutcell-cli run` (engine + simulated drives, fast clock) reports the same
// figures as `cutcell-cli simulate` for the default job, and leaves a run log.
#include "core/job/job_io.h"
#include "core/json/json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace cutcell {
namespace {

namespace fs = std::filesystem;

// Every number of a against the same path in b.
void expectSameNumbers(const json::Value& a, const json::Value& b, const std::string& path,
                       int& compared) {
    if (a.isObject()) {
        for (const auto& [k, v] : a.asObject()) {
            const json::Value* w = b.find(k);
            ASSERT_NE(w, nullptr) << path << "." << k;
            expectSameNumbers(v, *w, path + "." + k, compared);
        }
    } else if (a.isArray()) {
        ASSERT_EQ(a.asArray().size(), b.asArray().size()) << path;
        for (size_t i = 0; i < a.asArray().size(); ++i)
            expectSameNumbers(a.asArray()[i], b.asArray()[i], path + "[" + std::to_string(i) + "]",
                              compared);
    } else if (a.isNumber()) {
        EXPECT_NEAR(a.asNumber(), b.asNumber(), 1e-9 * std::max(1.0, std::fabs(b.asNumber())))
            << path;
        ++compared;
    }
}

// The rigid-body arm without Coulomb friction: the run's drives settle at the first cut point to
// rounding, as simulate starts, so both give the same figures (with friction the loops hunt
// before Start and the figures agree only in order: EngineMotion.FastClockRunOfTheDefaultJob*).
TEST(CliRun, RigidBodyJobGivesTheSameFiguresAsSimulateAndWritesARunLog) {
    const fs::path dir =
        fs::temp_directory_path() / ("cutcell_cli_run_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string job =
        std::string(CUTCELL_SOURCE_DIR) + "/tests/data/robot_rigid_frictionless_job.json";
    const std::string cli = CUTCELL_CLI;
    const fs::path runJson = dir / "run.json", simJson = dir / "sim.json", runs = dir / "runs";
    ASSERT_EQ(std::system((cli + " run " + job + " --quiet --runs " + runs.string() + " --report " +
                           runJson.string() + " 2>/dev/null")
                              .c_str()),
              0);
    ASSERT_EQ(
        std::system(
            (cli + " simulate " + job + " --report " + simJson.string() + " >/dev/null").c_str()),
        0);
    const json::Value run = json::parse(readTextFile(runJson.string()));
    const json::Value sim = json::parse(readTextFile(simJson.string()));
    int compared = 0;
    expectSameNumbers(sim, run, "", compared);
    EXPECT_GT(compared, 40);
    // One run folder with the three files.
    int folders = 0;
    for (const auto& entry : fs::directory_iterator(runs)) {
        if (!entry.is_directory()) continue;
        ++folders;
        for (const char* f : {"job.json", "events.log", "summary.json"})
            EXPECT_TRUE(fs::exists(entry.path() / f)) << f;
    }
    EXPECT_EQ(folders, 1);
    fs::remove_all(dir);
}

} // namespace
} // namespace cutcell
