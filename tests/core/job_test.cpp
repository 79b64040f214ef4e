// Job files: defaults, round trips, and rejection messages that name key, value, unit, limit.
#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <utility>

using namespace cutcell;

namespace {

json::Value defaultDoc() {
    return json::parse(defaultJobText());
}

json::Value* member(json::Value& v, const std::string& dotted) {
    json::Value* cur = &v;
    size_t start = 0;
    while (true) {
        const size_t dot = dotted.find('.', start);
        const std::string key =
            dotted.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
        json::Value* next = nullptr;
        for (auto& [k, val] : cur->asObject())
            if (k == key) next = &val;
        if (!next) return nullptr;
        cur = next;
        if (dot == std::string::npos) return cur;
        start = dot + 1;
    }
}

std::string rejection(const std::function<void(json::Value&)>& mutate) {
    json::Value doc = defaultDoc();
    mutate(doc);
    try {
        parseJob(json::write(doc));
    } catch (const JobError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Job, DefaultJobIsValidAndReproducesTheSeedSetUp) {
    const Job job = defaultJob();
    EXPECT_TRUE(validateJob(job).empty());
    const auto seed = seedDhTable();
    for (size_t i = 0; i < seed.size(); ++i) {
        EXPECT_EQ(cutcell::pipeRobotSpec(job).dh[i].d_mm, seed[i].d_mm);
        EXPECT_EQ(cutcell::pipeRobotSpec(job).dh[i].a_mm, seed[i].a_mm);
        EXPECT_EQ(cutcell::pipeRobotSpec(job).dh[i].min_deg, seed[i].min_deg);
        EXPECT_EQ(cutcell::pipeRobotSpec(job).dh[i].max_deg, seed[i].max_deg);
    }
    EXPECT_EQ(job.sim.duration_s, 30);
    EXPECT_FALSE(job.description.empty());
}

TEST(Job, JsonRoundTripIsIdentical) {
    const Job job = defaultJob();
    const std::string once = json::write(jobToJson(job));
    const std::string twice = json::write(jobToJson(parseJob(once)));
    EXPECT_EQ(once, twice);
}

TEST(Job, AtomicSaveLeavesNoTemporaryAndReloads) {
    const auto dir = std::filesystem::temp_directory_path() / "cutcell_job_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "job.json").string();
    Job job = defaultJob();
    job.name = "saved";
    saveJobFile(job, path);
    job.name = "saved again";
    saveJobFile(job, path);
    EXPECT_EQ(loadJobFile(path).name, "saved again");
    int files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir))
        ++files;
    EXPECT_EQ(files, 1);
    EXPECT_THROW(saveJobFile(job, (dir / "missing" / "job.json").string()), JobError);
    std::filesystem::remove_all(dir);
}

struct BadValue {
    const char* key;
    double value;
    std::vector<std::string> expected; // every fragment must appear in the message
};

class JobRejects : public ::testing::TestWithParam<BadValue> {};

TEST_P(JobRejects, MessageNamesKeyValueUnitAndLimit) {
    const BadValue& b = GetParam();
    const std::string msg = rejection([&](json::Value& doc) {
        json::Value* m = member(doc, b.key);
        ASSERT_NE(m, nullptr) << b.key;
        *m = json::Value(b.value);
    });
    ASSERT_FALSE(msg.empty()) << b.key << " = " << b.value << " was accepted";
    for (const auto& frag : b.expected)
        EXPECT_NE(msg.find(frag), std::string::npos) << msg << "\n  missing: " << frag;
}

INSTANTIATE_TEST_SUITE_P(
    Table, JobRejects,
    ::testing::Values(
        BadValue{"branch_pipe.radius_mm",
                 70,
                 {"branch_pipe.radius_mm = 70 mm", "|eccentricity_mm| + branch radius",
                  "main_pipe.radius_mm = 57.15 mm"}},
        BadValue{
            "eccentricity_mm",
            40,
            {"|eccentricity_mm| + branch radius = 64.15 mm", "<= main_pipe.radius_mm = 57.15 mm"}},
        BadValue{"angle_deg", 0, {"angle_deg = 0 deg", "[0.1, 90] deg"}},
        BadValue{"angle_deg", 95, {"angle_deg = 95 deg", "[0.1, 90] deg"}},
        BadValue{"main_pipe.wall_mm", -1, {"main_pipe.wall_mm = -1 mm", "outside [0.1, 500] mm"}},
        BadValue{"branch_pipe.wall_mm",
                 30,
                 {"branch_pipe.wall_mm = 30 mm", "less than branch_pipe.radius_mm = 24.15 mm"}},
        BadValue{"cut.speed_mm_s", 0, {"cut.speed_mm_s = 0 mm/s", "outside [0.1, 500] mm/s"}},
        BadValue{"cut.bevel_deg", 75, {"cut.bevel_deg = 75 deg", "[-60, 60] deg"}},
        BadValue{"sim.period_s", 0.5, {"sim.period_s = 0.5 s", "[0.0001, 0.02] s"}},
        BadValue{"sim.duration_s", -3, {"sim.duration_s = -3 s", "[0.1, 3600] s"}}));

TEST(Job, TableRowsAreCheckedWithTheirIndex) {
    const std::string msg = rejection([](json::Value& doc) {
        member(doc, "controller")->asArray()[3].set("tau_f_s", json::Value(-0.01));
    });
    EXPECT_NE(msg.find("controller[3].tau_f_s = -0.01 s"), std::string::npos) << msg;
    const std::string lim = rejection([](json::Value& doc) {
        auto& row = member(doc, "robot.dh")->asArray()[2];
        row.set("min_deg", json::Value(50));
    });
    EXPECT_NE(lim.find("robot.dh[2].min_deg = 50 deg must be below robot.dh[2].max_deg = 45 deg"),
              std::string::npos)
        << lim;
    const std::string rows =
        rejection([](json::Value& doc) { member(doc, "plant")->asArray().pop_back(); });
    EXPECT_NE(rows.find("plant has 5 rows; it needs 6"), std::string::npos) << rows;
}

TEST(Job, StructuralErrorsAreNamed) {
    EXPECT_NE(rejection([](json::Value& d) {
                  d.set("method", json::Value("sideways"));
              }).find("method = \"sideways\" is not one of \"static_pipe\", \"rotating_pipe\""),
              std::string::npos);
    EXPECT_NE(rejection([](json::Value& d) {
                  member(d, "main_pipe")->set("radius_mm", json::Value("big"));
              }).find("main_pipe.radius_mm must be a number in mm, found string"),
              std::string::npos);
    EXPECT_NE(rejection([](json::Value& d) {
                  d.set("schema", json::Value(3));
              }).find("schema = 3 is not supported"),
              std::string::npos);
    json::Value doc = defaultDoc();
    auto& obj = doc.asObject();
    obj.erase(
        std::remove_if(obj.begin(), obj.end(), [](const auto& kv) { return kv.first == "cut"; }),
        obj.end());
    try {
        parseJob(json::write(doc));
        FAIL();
    } catch (const JobError& e) {
        EXPECT_NE(std::string(e.what()).find("missing required section machine.cut"),
                  std::string::npos);
    }
    try {
        parseJob("{ \"schema\": 1, ");
        FAIL();
    } catch (const JobError& e) {
        EXPECT_NE(std::string(e.what()).find("not valid JSON"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("line 1"), std::string::npos);
    }
}

// Issue 27 (6): counts_per_unit = 3e7 was valid and θ3's counts overflowed int32 (an error of
// 143.9° over CAN, exit 0). An axis with a travel keeps every position of it inside a drive's
// 32-bit position; the bound follows from the travel and the refusal gives it.
TEST(Job, CountsPerUnitKeepTheWholeTravelInsideA32BitPosition) {
    Job job = defaultJob();
    const DhRow& r = pipeRobotSpec(job).dh[3];
    const double reach = std::max(std::fabs(r.min_deg), std::fabs(r.max_deg));
    const double bound = 2147483647.0 / reach;
    const auto issueOf = [](const Job& j) {
        for (const JobIssue& i : validateJob(j))
            if (i.key == "devices.counts_per_unit[3]") return i.message;
        return std::string();
    };
    job.devices.counts_per_unit[3] = bound * 0.999;
    EXPECT_EQ(issueOf(job), "");
    job.devices.counts_per_unit[3] = bound * 1.001;
    const std::string m = issueOf(job);
    EXPECT_NE(m.find("counts/deg"), std::string::npos) << m;
    EXPECT_NE(m.find("32-bit position (2147483647 counts)"), std::string::npos) << m;
    EXPECT_NE(m.find("theta3"), std::string::npos) << m;
    // The bound it names is the one that holds.
    const size_t at = m.find("at most ");
    ASSERT_NE(at, std::string::npos) << m;
    job.devices.counts_per_unit[3] = std::stod(m.substr(at + 8));
    EXPECT_EQ(issueOf(job), "") << "the bound named: " << m.substr(at);
}

// The robot's data lives in its own section (Job::machine_spec), read back by pipeRobotSpec():
// the shipped job holds it; a job built in code reads the defaults until it is edited; another
// machine's job is refused by name, never read as the robot's.
TEST(Job, TheRobotsDataIsItsOwnSection) {
    const Job shipped = defaultJob();
    ASSERT_NE(shipped.machine_spec.as<PipeRobotSpec>(), nullptr);
    EXPECT_EQ(pipeRobotSpec(shipped).dh[0].d_mm, seedDhTable()[0].d_mm);
    EXPECT_GT(pipeRobotSpec(shipped).controller[1].kp, 0);

    Job built;
    EXPECT_TRUE(built.machine_spec.empty());
    EXPECT_EQ(pipeRobotSpec(std::as_const(built)).method, CutMethod::RotatingPipe);
    pipeRobotSpec(built).method = CutMethod::StaticPipe;
    ASSERT_NE(built.machine_spec.as<PipeRobotSpec>(), nullptr);
    EXPECT_EQ(pipeRobotSpec(std::as_const(built)).method, CutMethod::StaticPipe);

    const Job saw = parseJob(
        readTextFile(std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/flying_saw_job.json"));
    try {
        (void)pipeRobotSpec(saw);
        FAIL() << "a flying-saw job read as the robot's";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("not the pipe robot's"), std::string::npos)
            << e.what();
    }
    // Written and read back, the section is the same.
    const Job back = parseJob(json::write(jobToJson(shipped)));
    EXPECT_EQ(json::write(jobToJson(back)), json::write(jobToJson(shipped)));
}

// Issue 27 (9, 10): messages stay short and name the key; the typo gets its nearest key, in any
// case; a NUL byte, a 400-digit number and an absurd entry past the axis count are refused.
TEST(Job, MessagesAreShortAndNameTheKeyAndTheTypo) {
    const std::string longArray = rejection([](json::Value& d) {
        json::Array ids;
        for (int i = 1; i <= 100000; ++i)
            ids.emplace_back(i % 127 + 1);
        member(d, "devices")->set("node_ids", json::Value(std::move(ids)));
    });
    EXPECT_NE(longArray.find("devices.node_ids = [2, 3, 4"), std::string::npos) << longArray;
    EXPECT_NE(longArray.find("(100000 entries)"), std::string::npos) << longArray;
    EXPECT_LT(longArray.size(), 300u) << longArray; // was 3 MB

    // A common section's name in the wrong case: schema 1 (the shipped job) and schema 2.
    const std::string upper = rejection([](json::Value& d) {
        json::Value devices = *member(d, "devices");
        auto& obj = d.asObject();
        obj.erase(std::remove_if(obj.begin(), obj.end(),
                                 [](const auto& kv) { return kv.first == "devices"; }),
                  obj.end());
        d.set("DEVICES", devices);
    });
    EXPECT_NE(upper.find("unknown key \"DEVICES\" (did you mean \"devices\"?)"), std::string::npos)
        << upper;
    const std::string upgraded = upgradeJobText(defaultJobText());
    std::string renamed = upgraded;
    renamed.replace(renamed.find("\"devices\""), 9, "\"Devices\"");
    try {
        parseJob(renamed);
        ADD_FAILURE() << "schema 2 with \"Devices\" accepted";
    } catch (const JobError& e) {
        EXPECT_NE(std::string(e.what()).find("did you mean \"devices\""), std::string::npos)
            << e.what();
    }

    // A required key misspelt: the missing key and the look-alike that is there.
    const std::string misspelt = rejection([](json::Value& d) {
        json::Value* sim = member(d, "sim");
        const json::Value period = *member(*sim, "period_s");
        auto& o = sim->asObject();
        std::erase_if(o, [](const auto& kv) { return kv.first == "period_s"; });
        sim->set("period_S", period);
    });
    EXPECT_NE(misspelt.find("missing required key sim.period_s"), std::string::npos) << misspelt;
    EXPECT_NE(misspelt.find("found \"sim.period_S\""), std::string::npos) << misspelt;
    // Two byte order marks: one is accepted, a second is not text of a JSON document.
    try {
        parseJob("\xEF\xBB\xBF\xEF\xBB\xBF" + defaultJobText());
        ADD_FAILURE() << "two byte order marks accepted";
    } catch (const JobError& e) {
        EXPECT_NE(std::string(e.what()).find("byte order mark"), std::string::npos) << e.what();
    }
    EXPECT_NO_THROW(parseJob("\xEF\xBB\xBF" + defaultJobText()));
    // A NUL byte after the document: refused with its place (was read as valid).
    try {
        parseJob(defaultJobText() + std::string(1, '\0'));
        ADD_FAILURE() << "a trailing NUL byte was accepted";
    } catch (const JobError& e) {
        EXPECT_NE(std::string(e.what()).find("NUL byte"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("line "), std::string::npos) << e.what();
    }
    // A 400-digit number: its line and key, not the number whole (was "line 0, column 0").
    try {
        parseJob("{\n  \"sim\": {\"period_s\": 1" + std::string(400, '0') + "}}");
        ADD_FAILURE();
    } catch (const JobError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("line 2"), std::string::npos) << what;
        EXPECT_NE(what.find("sim.period_s"), std::string::npos) << what;
        EXPECT_EQ(what.find("line 0"), std::string::npos) << what;
        EXPECT_LT(what.size(), 250u) << what;
    }
}
