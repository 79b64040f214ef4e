// The machine framework: registry, job schema 2 and the migration of schema-1 files, unknown
// and duplicate keys, and the bad input of issue 11 (every number has a physical range).
#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace cutcell;

namespace {

std::string shipped(const std::string& name) {
    return readTextFile(std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/" + name);
}

// The shipped default job with one piece of text replaced (the value of a key).
std::string edited(const std::string& text, const std::string& from, const std::string& to) {
    std::string s = text;
    const size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
    return s;
}

std::string refusal(const std::string& text) {
    try {
        parseJob(text);
    } catch (const JobError& e) {
        return e.what();
    }
    return {};
}

// Every plan file of a job, concatenated (the same plan gives the same text).
std::string planFiles(const Job& job) {
    const MachineModule& m = machineFor(job);
    const MachinePlan plan = m.plan(job, {});
    EXPECT_TRUE(plan.ok()) << plan.outcome.message;
    std::string out;
    for (const ExportInfo& e : m.exports())
        if (e.plan_file) out += m.exportFile(e.id, job, plan);
    return out;
}

} // namespace

TEST(Machines, RegistryListsBothMachinesWithAxesAndExports) {
    const auto all = machines();
    ASSERT_GE(all.size(), 2u);
    for (const MachineModule* m : all) {
        EXPECT_EQ(findMachine(m->id()), m);
        const Job job = m->defaultJob();
        EXPECT_EQ(machineFor(job).id(), m->id());
        EXPECT_FALSE(m->axes(job).empty());
        EXPECT_FALSE(m->exports().empty());
        EXPECT_TRUE(validateJob(job).empty()) << m->id() << ": " << validateJob(job)[0].message;
    }
    EXPECT_EQ(findMachine("no_such_machine"), nullptr);
}

TEST(Machines, ShippedSchema1JobsUpgradeAndPlanTheSame) {
    for (const char* name : {"default_job.json", "profile_cutter_job.json"}) {
        SCOPED_TRACE(name);
        const std::string v1 = shipped(name);
        const Job before = parseJob(v1);
        const std::string v2 = upgradeJobText(v1);
        EXPECT_NE(v2.find("\"schema\": 2"), std::string::npos);
        EXPECT_NE(v2.find("\"kind\": "), std::string::npos);
        const Job after = parseJob(v2);
        EXPECT_EQ(after.machine, before.machine);
        EXPECT_EQ(planFiles(after), planFiles(before));
        // Saving writes schema 2, which reads back to the same plan again.
        const std::string saved = json::write(jobToJson(after));
        EXPECT_EQ(upgradeJobText(saved), upgradeJobText(upgradeJobText(saved)));
        EXPECT_EQ(planFiles(parseJob(saved)), planFiles(before));
    }
}

TEST(Machines, AMachineOnlyReadsItsOwnKeys) {
    // The profile cutter needs no DH table, controller or plant rows.
    const std::string v2 = upgradeJobText(shipped("profile_cutter_job.json"));
    EXPECT_EQ(v2.find("\"controller\""), std::string::npos);
    EXPECT_EQ(v2.find("\"dh\""), std::string::npos);
    EXPECT_NO_THROW(parseJob(v2));
    // ... and refuses them in a schema-2 file.
    const std::string withDh =
        edited(v2, "\"profile_cutter\": {", "\"robot\": {\"dh\": []},\n    \"profile_cutter\": {");
    EXPECT_NE(refusal(withDh).find("unknown key \"machine.robot\""), std::string::npos)
        << refusal(withDh);
}

TEST(Machines, UnknownKeysAreRefusedWithTheNearestKey) {
    const std::string text =
        edited(shipped("default_job.json"), "\"bevel_deg\"", "\"bevel_degree\"");
    const std::string why = refusal(text);
    EXPECT_NE(why.find("unknown key \"machine.cut.bevel_degree\""), std::string::npos) << why;
    EXPECT_NE(why.find("did you mean \"machine.cut.bevel_deg\"?"), std::string::npos) << why;
    const std::string top = edited(shipped("default_job.json"), "\"sim\"", "\"simm\"");
    EXPECT_NE(refusal(top).find("simm"), std::string::npos) << refusal(top);
}

TEST(Machines, ManyUnknownKeysAreRefusedNamingTheFirst) {
    std::string text = shipped("default_job.json");
    std::string extra;
    for (int i = 0; i < 100000; ++i)
        extra += "\"k" + std::to_string(i) + "\": 1, ";
    text.insert(text.find('{') + 1, extra);
    const std::string why = refusal(text);
    EXPECT_NE(why.find("unknown key \"machine.k0\""), std::string::npos) << why.substr(0, 200);
}

TEST(Machines, DuplicateKeysBomAndSizeCap) {
    const std::string dup = edited(shipped("default_job.json"), "\"angle_deg\": 90,",
                                   "\"angle_deg\": 90, \"angle_deg\": 45,");
    EXPECT_NE(refusal(dup).find("duplicate key \"angle_deg\""), std::string::npos) << refusal(dup);
    EXPECT_NO_THROW(parseJob("\xEF\xBB\xBF" + shipped("default_job.json")));
    std::string huge = shipped("default_job.json");
    huge.insert(huge.find("\"name\": \"") + 9, std::string(17u << 20, 'x'));
    const std::string why = refusal(huge);
    EXPECT_NE(why.find("16 MiB"), std::string::npos) << why.substr(0, 200);
    EXPECT_LT(why.size(), 400u);
    // A long value is echoed cut short.
    const std::string longMethod = edited(shipped("default_job.json"), "\"rotating_pipe\"",
                                          "\"" + std::string(5000, 'm') + "\"");
    const std::string m = refusal(longMethod);
    EXPECT_NE(m.find("machine.method"), std::string::npos) << m;
    EXPECT_LT(m.size(), 300u) << m;
}

TEST(Machines, NumbersHavePhysicalRanges) {
    const std::string job = shipped("default_job.json");
    const struct {
        const char* from;
        const char* to;
        const char* key;
    } cases[] = {
        {"\"angle_deg\": 90", "\"angle_deg\": 5e-324",
         "machine.angle_deg = 4.94066e-324 deg is outside [0.1, 90] deg"},
        {"\"speed_mm_s\": 4.397", "\"speed_mm_s\": 0.001",
         "machine.cut.speed_mm_s = 0.001 mm/s is outside [0.1, 500] mm/s"},
        {"\"speed_mm_s\": 4.397", "\"speed_mm_s\": 1e-300",
         "machine.cut.speed_mm_s = 1e-300 mm/s is outside [0.1, 500] mm/s"},
        {"\"mass_kg\": 1.9049", "\"mass_kg\": -1",
         "machine.robot.links[0].mass_kg = -1 kg is outside [0, 500] kg"},
        {"\"ixx_kg_cm2\": 246.509", "\"ixx_kg_cm2\": 900", "break the triangle inequality"},
        {"\"gear_ratio\": 50", "\"gear_ratio\": 0.5",
         "machine.robot.drives[0].gear_ratio = 0.5  is outside [1, 1000]"},
        {"\"kp_nm_per_rad\": 889.06", "\"kp_nm_per_rad\": 1e308",
         "machine.controller[0].kp_nm_per_rad = 1e+308 N m/rad is outside [0, 1e+06] N m/rad"},
    };
    for (const auto& c : cases) {
        const std::string why = refusal(edited(job, c.from, c.to));
        EXPECT_NE(why.find(c.key), std::string::npos) << why;
    }
    Job j = defaultJob();
    auto firstIssue = [](const Job& checked) {
        const auto issues = validateJob(checked);
        return issues.empty() ? std::string() : issues.front().message;
    };
    j.cut.speed_mm_s = 0.001;
    EXPECT_NE(firstIssue(j).find("cut.speed_mm_s = 0.001 mm/s"), std::string::npos)
        << firstIssue(j);
    j.cut.speed_mm_s = 1e-300;
    EXPECT_NE(firstIssue(j).find("cut.speed_mm_s = 1e-300 mm/s"), std::string::npos)
        << firstIssue(j);
    j = defaultJob();
    cutcell::pipeRobotSpec(j).controller[2].kp = 1e308;
    EXPECT_NE(firstIssue(j).find("controller[2].kp_nm_per_rad = 1e+308 N m/rad is outside"),
              std::string::npos)
        << firstIssue(j);
    j = defaultJob();
    j.main_pipe.length_mm = 40; // the branch's hole is 48.3 mm wide at 90 deg
    j.branch_pipe.radius_mm = 24.15;
    EXPECT_NE(firstIssue(j).find("main_pipe.length_mm = 40 mm is shorter than the cut"),
              std::string::npos)
        << firstIssue(j);
    j = defaultJob();
    j.devices.bitrate_bps = 125001;
    EXPECT_NE(firstIssue(j).find("devices.bitrate_bps = 125001 bit/s is not a CAN bit rate"),
              std::string::npos)
        << firstIssue(j);
}

TEST(Machines, FloatToIntConversionsAreRangeCheckedFirst) {
    const std::string job = shipped("default_job.json");
    for (const char* bad : {"-1e308", "1e10", "3.5"}) {
        const std::string ids =
            refusal(edited(job, "\"node_ids\": [1,", std::string("\"node_ids\": [") + bad + ","));
        EXPECT_NE(ids.find("devices.node_ids[0]"), std::string::npos) << ids;
    }
    const std::string rate =
        refusal(edited(job, "\"bitrate_bps\": 1000000", "\"bitrate_bps\": 1e10"));
    EXPECT_NE(rate.find("devices.bitrate_bps = 1e+10 bit/s is outside"), std::string::npos) << rate;
}

TEST(Machines, AMachineWithoutCanDrivesRefusesCanopen) {
    const std::string text = edited(shipped("profile_cutter_job.json"), "\"kind\": \"simulated\"",
                                    "\"kind\": \"canopen\"");
    const std::string why = refusal(text);
    EXPECT_NE(why.find("devices.kind = \"canopen\": the profile cutter"), std::string::npos) << why;
}

// devices.node_ids / counts_per_unit hold one entry per axis of the machine (up to 8); files
// written when every machine had 6 slots still load; any other length is refused naming the
// key, the value and the machine's axis count.
TEST(Machines, DeviceArraysFollowTheMachinesAxisCount) {
    const std::string steel = shipped("section_steel_job.json");
    ASSERT_NE(steel.find("\"node_ids\": [1, 2, 3, 4, 5, 6]"), std::string::npos);
    const Job legacy = parseJob(steel); // 6 entries: the first six axes, 7 and 8 by default
    EXPECT_EQ(legacy.devices.node_ids[5], 6);
    EXPECT_EQ(legacy.devices.node_ids[6], 7);
    EXPECT_EQ(legacy.devices.node_ids[7], 8);
    const std::string written = json::write(jobToJson(legacy));
    EXPECT_NE(written.find("\"node_ids\": [1, 2, 3, 4, 5, 6, 7, 8]"), std::string::npos) << written;
    const std::string eight = edited(written, "\"node_ids\": [1, 2, 3, 4, 5, 6, 7, 8]",
                                     "\"node_ids\": [11, 12, 13, 14, 15, 16, 17, 18]");
    const Job custom = parseJob(eight);
    EXPECT_EQ(custom.devices.node_ids[7], 18);
    EXPECT_EQ(json::write(jobToJson(custom)), eight); // round trip
    const std::string five =
        refusal(edited(steel, "\"node_ids\": [1, 2, 3, 4, 5, 6]", "\"node_ids\": [1, 2, 3, 4, 5]"));
    EXPECT_NE(five.find("devices.node_ids = [1, 2, 3, 4, 5] has 5 entries"), std::string::npos)
        << five;
    EXPECT_NE(five.find("has 8 axes"), std::string::npos) << five;
    const std::string seven = refusal(
        edited(written, "\"counts_per_unit\": [1000, 1000, 1000, 1000, 1000, 1000, 1000, 1000]",
               "\"counts_per_unit\": [1000, 1000, 1000, 1000, 1000, 1000, 1000]"));
    EXPECT_NE(seven.find("devices.counts_per_unit = [1000, 1000, 1000, 1000, 1000, 1000, 1000] "
                         "has 7 entries"),
              std::string::npos)
        << seven;
    const std::string twice =
        refusal(edited(written, "[1, 2, 3, 4, 5, 6, 7, 8]", "[1, 2, 3, 4, 5, 6, 7, 7]"));
    EXPECT_NE(twice.find("devices.node_ids[7] = 7 is used twice"), std::string::npos) << twice;

    // The pipe robot (6 axes) writes what it always wrote.
    const std::string robot = json::write(jobToJson(parseJob(shipped("default_job.json"))));
    EXPECT_NE(robot.find("\"node_ids\": [1, 2, 3, 4, 5, 6],"), std::string::npos) << robot;
    EXPECT_EQ(robot.find("sensor_node_ids"), std::string::npos);

    // The flying saw: 4 axes and its line encoder's node (after the axes by default).
    const std::string saw = json::write(jobToJson(parseJob(shipped("flying_saw_job.json"))));
    EXPECT_NE(saw.find("\"node_ids\": [1, 2, 3, 4],"), std::string::npos) << saw;
    EXPECT_NE(saw.find("\"sensor_node_ids\": [5],"), std::string::npos) << saw;
    const std::string clash =
        refusal(edited(saw, "\"sensor_node_ids\": [5]", "\"sensor_node_ids\": [3]"));
    EXPECT_NE(clash.find("devices.sensor_node_ids[0] = 3 is the node of axis 2"), std::string::npos)
        << clash;
    const std::string two =
        refusal(edited(saw, "\"sensor_node_ids\": [5]", "\"sensor_node_ids\": [5, 6]"));
    EXPECT_NE(two.find("devices.sensor_node_ids = [5, 6]: the machine \"flying_saw\" reads 1 "
                       "sensor"),
              std::string::npos)
        << two;
    const std::string unknown = refusal(edited(saw, "\"sensor_node_ids\"", "\"sensor_nodes\""));
    EXPECT_NE(unknown.find("sensor_nodes"), std::string::npos) << unknown;
}
