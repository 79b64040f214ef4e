// Profile-cutter job keys (round trip, validation messages) and the CLI over them.
#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/profile_cutter_spec.h"
#include "profile_test_util.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace cutcell {
namespace {

TEST(ProfileJob, ExampleLoadsAndRoundTrips) {
    const Job job = test::exampleProfileJob();
    EXPECT_EQ(job.machine, "profile_cutter_2axis");
    ASSERT_EQ(cutcell::profileCutterSpec(job).other_branches.size(), 1u);
    const std::string once = json::write(jobToJson(job));
    const Job again = jobFromJson(json::parse(once));
    EXPECT_EQ(json::write(jobToJson(again)), once);
    EXPECT_EQ(cutcell::profileCutterSpec(again).steps_per_rev_a,
              cutcell::profileCutterSpec(job).steps_per_rev_a);
    EXPECT_EQ(cutcell::profileCutterSpec(again).other_branches[0].position_mm,
              cutcell::profileCutterSpec(job).other_branches[0].position_mm);
    // An explicit hole position survives too.
    Job hole = job;
    cutcell::profileCutterSpec(hole).branch_position_auto = false;
    cutcell::profileCutterSpec(hole).branch_position_mm = 321.5;
    const Job back = jobFromJson(jobToJson(hole));
    EXPECT_FALSE(cutcell::profileCutterSpec(back).branch_position_auto);
    EXPECT_EQ(cutcell::profileCutterSpec(back).branch_position_mm, 321.5);
}

TEST(ProfileJob, RobotJobKeepsItsShape) {
    const Job robot = defaultJob();
    const json::Value doc = jobToJson(robot);
    EXPECT_EQ(doc.find("profile_cutter"), nullptr);
    EXPECT_EQ(doc.find("other_branches"), nullptr);
    EXPECT_EQ(robot.machine_spec.as<cutcell::ProfileCutterSpec>(), nullptr);
}

std::string firstMessageFor(const Job& job, const std::string& key) {
    for (const auto& issue : validateJob(job))
        if (issue.key == key) return issue.message;
    return "";
}

TEST(ProfileJob, BadValuesNameKeyValueUnitAndLimit) {
    Job job = test::exampleProfileJob();
    cutcell::profileCutterSpec(job).other_branches[0].radius_mm = 80;
    cutcell::profileCutterSpec(job).other_branches[0].eccentricity_mm = 10;
    EXPECT_EQ(
        firstMessageFor(job, "other_branches[0].radius_mm"),
        "machine.other_branches[0].radius_mm = 80 mm does not fit: |eccentricity_mm| + radius = 90 "
        "mm must be <= "
        "main_pipe.radius_mm = 84.15 mm");
    job = test::exampleProfileJob();
    cutcell::profileCutterSpec(job).other_branches[0].angle_deg = 180;
    EXPECT_EQ(
        firstMessageFor(job, "other_branches[0].angle_deg"),
        "machine.other_branches[0].angle_deg = 180 deg is outside [0.1, 179.9] deg (angle to the "
        "main axis)");
    job = test::exampleProfileJob();
    cutcell::profileCutterSpec(job).other_branches[0].angle_deg =
        job.angle_deg; // parallel to the cut branch
    EXPECT_NE(firstMessageFor(job, "other_branches[0].angle_deg").find("must differ by >= 1 deg"),
              std::string::npos);
    job = test::exampleProfileJob();
    cutcell::profileCutterSpec(job).steps_per_rev_a = 4;
    EXPECT_EQ(
        firstMessageFor(job, "profile_cutter.steps_per_rev_a"),
        "machine.profile_cutter.steps_per_rev_a = 4 steps/rev is outside [8, 100000] steps/rev");
    job = test::exampleProfileJob();
    cutcell::profileCutterSpec(job).mm_per_pulse_x = 0;
    EXPECT_EQ(firstMessageFor(job, "profile_cutter.mm_per_pulse_x"),
              "machine.profile_cutter.mm_per_pulse_x = 0 mm/pulse is outside [1e-05, 1] mm/pulse");
    job = test::exampleProfileJob();
    job.cut.bevel_deg = 15;
    EXPECT_EQ(firstMessageFor(job, "cut.bevel_deg"),
              "machine.cut.bevel_deg = 15 deg: the 2-axis profile cutter cuts square only (0 deg)");
}

TEST(ProfileJob, NonIntegerStepsAreRejectedWhenRead) {
    json::Value doc = jobToJson(test::exampleProfileJob());
    json::Value machine = *doc.find("machine"); // schema 2: the machine's own section
    json::Value pc = *machine.find("profile_cutter");
    pc.set("steps_per_rev_a", 400.5);
    machine.set("profile_cutter", pc);
    doc.set("machine", machine);
    try {
        jobFromJson(doc);
        FAIL() << "accepted 400.5 steps/rev";
    } catch (const JobError& e) {
        EXPECT_STREQ(e.what(),
                     "machine.profile_cutter.steps_per_rev_a = 400.5 steps/rev must be a whole "
                     "number");
    }
}

int runCli(const std::string& args, std::string* out) {
    FILE* p = ::popen((std::string(CUTCELL_CLI) + " " + args + " 2>&1").c_str(), "r");
    std::array<char, 4096> buf{};
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0)
        out->append(buf.data(), n);
    const int status = ::pclose(p);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

size_t lineCount(const std::filesystem::path& f) {
    std::ifstream in(f);
    size_t n = 0;
    std::string line;
    while (std::getline(in, line))
        ++n;
    return n;
}

TEST(ProfileCli, ExportPlanAndValidate) {
    const std::string job =
        std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/profile_cutter_job.json";
    const auto dir =
        std::filesystem::temp_directory_path() / ("cutcell_cli_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::string out;
    ASSERT_EQ(runCli("validate " + job, &out), 0) << out;
    EXPECT_NE(out.find("profile_cutter_2axis"), std::string::npos) << out;
    out.clear();
    const std::string g = (dir / "cut.ngc").string(), svg = (dir / "t.svg").string(),
                      pdf = (dir / "t.pdf").string();
    ASSERT_EQ(runCli("export " + job + " --gcode " + g + " --template-svg " + svg +
                         " --template-pdf " + pdf,
                     &out),
              0)
        << out;
    EXPECT_GT(std::filesystem::file_size(g), 1000u);
    EXPECT_GT(std::filesystem::file_size(svg), 1000u);
    EXPECT_GT(std::filesystem::file_size(pdf), 1000u);
    out.clear();
    ASSERT_EQ(runCli("export " + job + " --template-svg " + (dir / "only.svg").string(), &out), 0)
        << out;
    EXPECT_FALSE(std::filesystem::exists(dir / "cut2.ngc"));
    out.clear();
    EXPECT_EQ(runCli("export " + job, &out), 64) << out;
    out.clear();
    ASSERT_EQ(runCli("plan " + job + " --out " + (dir / "plan").string(), &out), 0) << out;
    const int n = cutcell::profileCutterSpec(test::exampleProfileJob()).steps_per_rev_a;
    EXPECT_EQ(lineCount(dir / "plan" / "path.csv"),
              static_cast<size_t>(n) + 2); // header + n + closing row
    out.clear();
    EXPECT_EQ(runCli("simulate " + job, &out), 64) << out;
    // G-code needs the 2-axis machine; the robot's job gets a clear refusal.
    out.clear();
    const std::string robot = std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/default_job.json";
    EXPECT_EQ(runCli("export " + robot + " --gcode " + (dir / "robot.ngc").string(), &out), 2)
        << out;
    EXPECT_NE(out.find("profile_cutter_2axis"), std::string::npos) << out;
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace cutcell
