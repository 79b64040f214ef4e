// Who may change what (issue 25): the job diff that the station's file-open gate reads, and the
// level of each key. The diff by round trip (a job against itself: nothing; one change: exactly
// that key with both values); the levels by the issue's own words (a setter's speeds and bevel,
// an engineer's gains, DH table, limits, devices, E-STOP category) on every machine's keys.
#include "core/job/default_job.h"
#include "core/job/job_diff.h"
#include "core/machine/machine_module.h"
#include "core/machine/machine_registry.h"
#include "core/machine/parameter_level.h"

#include <gtest/gtest.h>

namespace cutcell {
namespace {

TEST(JobDiff, AJobAgainstItselfDiffersNowhereAndOneChangeIsThatKeyAlone) {
    for (const MachineModule* m : machines()) {
        const Job job = m->defaultJob();
        EXPECT_TRUE(changedKeys(job, job).empty()) << m->id();
        Job changed = job;
        changed.engine.feed_hold_decel_s = job.engine.feed_hold_decel_s + 0.25;
        const auto diff = changedKeys(job, changed);
        ASSERT_EQ(diff.size(), 1u) << m->id();
        EXPECT_EQ(diff[0].key, "engine.feed_hold_decel_s");
        EXPECT_EQ(std::stod(diff[0].to) - std::stod(diff[0].from), 0.25);
        EXPECT_EQ(levelToChange(diff[0].key, m), UserLevel::Engineer);
    }
}

TEST(ParameterLevel, TheIssuesExamplesOnTheRobotsKeys) {
    const MachineModule& robot = machineFor(defaultJob());
    EXPECT_EQ(levelToChange("cut.speed_mm_s", &robot), UserLevel::Setter);
    EXPECT_EQ(levelToChange("cut.bevel_deg", &robot), UserLevel::Setter);
    EXPECT_EQ(levelToChange("main_pipe.radius_mm", &robot), UserLevel::Setter);
    EXPECT_EQ(levelToChange("controller[2].kp_nm_per_rad", &robot), UserLevel::Engineer);
    EXPECT_EQ(levelToChange("robot.dh[1].a_mm", &robot), UserLevel::Engineer);
    EXPECT_EQ(levelToChange("engine.estop_category", &robot), UserLevel::Engineer);
    EXPECT_EQ(levelToChange("engine.following_error_limit_deg", &robot), UserLevel::Engineer);
    EXPECT_EQ(levelToChange("devices.node_ids[0]", &robot), UserLevel::Engineer);
    // A prefix is a section, not the start of a word: "robotic" is not "robot".
    EXPECT_FALSE(keyUnder("robotic.x", {"robot"}));
    EXPECT_TRUE(keyUnder("robot", {"robot"}));
    EXPECT_TRUE(keyUnder("drives[3].kp", {"drives"}));
}

// Every machine: its engine and devices keys are an engineer's, its own keys are split, and at
// least one of its own keys is a setter's (a machine whose every key needed an engineer would
// leave the setter nothing to set).
TEST(ParameterLevel, EveryMachineHasBothLevelsInItsOwnSection) {
    for (const MachineModule* m : machines()) {
        int setter = 0, engineer = 0;
        for (const ChangedKey& k : changedKeys(Job{}, m->defaultJob())) {
            if (k.key.rfind("machine.", 0) != 0 || k.key == "machine.kind") continue;
            (levelToChange(k.key, m) == UserLevel::Engineer ? engineer : setter)++;
        }
        EXPECT_GT(setter, 0) << m->id();
        EXPECT_GT(engineer, 0) << m->id();
    }
}

} // namespace
} // namespace cutcell
