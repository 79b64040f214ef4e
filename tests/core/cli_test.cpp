// cutcell-cli as a user runs it: exit codes, messages and the files it writes.
#include "core/common/c_format.h"
#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "core/machines/pipe_robot/pipe_robot_tuning.h"
#include "core/process/cut_chart.h"
#include "tests/support/run_cli.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <vector>

using namespace cutcell;
namespace fs = std::filesystem;

namespace {

using Result = test::CliResult;
using test::runCli;

fs::path tempDir(const std::string& name) {
    const fs::path d = fs::temp_directory_path() / ("cutcell_cli_" + name);
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::string defaultJobPath() {
    return std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/default_job.json";
}

} // namespace

TEST(Cli, ValidateAcceptsTheDefaultJob) {
    const Result r = runCli("validate " + defaultJobPath());
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("is valid"), std::string::npos);
}

TEST(Cli, InvalidJobExitsTwoWithTheKeyValueUnitAndLimit) {
    const fs::path dir = tempDir("invalid");
    Job job = defaultJob();
    job.branch_pipe.radius_mm = 80;
    saveJobFile(job, (dir / "bad.json").string());
    const Result r = runCli("validate " + (dir / "bad.json").string());
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("branch_pipe.radius_mm = 80 mm"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("main_pipe.radius_mm = 57.15 mm"), std::string::npos) << r.output;

    std::ofstream(dir / "broken.json") << "{ \"schema\": 1,\n  \"main_pipe\": {\"radius_mm\": 5";
    const Result b = runCli("simulate " + (dir / "broken.json").string());
    EXPECT_EQ(b.code, 2) << b.output;
    EXPECT_NE(b.output.find("line 2"), std::string::npos) << b.output;
}

// Issue 27 (10): a folder given as the job is an I/O error (exit 1), not an invalid job; an
// absurd counts_per_unit entry past the machine's axis count (a 6-entry list on the one-axis
// crank) is refused, naming its index.
TEST(Cli, AFolderIsAnIoErrorAndEveryCountsEntryIsChecked) {
    const fs::path dir = tempDir("folder_counts");
    const Result folder = runCli("validate " + dir.string());
    EXPECT_EQ(folder.code, 1) << folder.output;
    EXPECT_NE(folder.output.find("it is a folder"), std::string::npos) << folder.output;

    std::ifstream in(std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/quick_return_job.json");
    std::stringstream ss;
    ss << in.rdbuf();
    json::Value doc = json::parse(ss.str());
    json::Array counts;
    for (const double c : {1000.0, -1e308, 1000.0, 1000.0, 1000.0, 1000.0})
        counts.emplace_back(c);
    for (auto& [k, v] : doc.asObject())
        if (k == "devices") v.set("counts_per_unit", json::Value(std::move(counts)));
    std::ofstream(dir / "crank.json") << json::write(doc);
    const Result r = runCli("validate " + (dir / "crank.json").string());
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("devices.counts_per_unit[1] = -1e+308"), std::string::npos) << r.output;
}

// Issue 27 (10): a blade of no thickness, and a root face of -1e308 mm on a face without a
// groove (unused there, but a value of the file), were accepted.
TEST(Cli, AbsurdValuesAreRefusedAlsoWhereTheyAreUnused) {
    const fs::path dir = tempDir("absurd");
    // A shipped job with one text replaced: validate exits 2 with the expected message.
    const struct {
        const char* why;
        const char *job, *from, *to, *message;
    } cases[] = {
        {"a blade without kerf", "flying_saw_job.json", "\"kerf_mm\": 3", "\"kerf_mm\": 0",
         "machine.blade.kerf_mm = 0 mm is outside [0.1, 20] mm"},
        {"a root face where the groove is none", "section_steel_job.json", "\"root_face_mm\": 0",
         "\"root_face_mm\": -1e308", "machine.end_cut.flanges.root_face_mm = -1e+308 mm"},
        // OSMC's weights while another controller runs: q11 q22 overflowed to infinity and
        // passed "positive definite".
        {"q11 overflowing Q", "quick_return_job.json", "\"q11\": 900", "\"q11\": 1e300",
         "machine.control.osmc.q11 = 1e+300 1 is outside [1e-12, 1e+12] 1"},
        {"q12 overflowing Q", "quick_return_job.json", "\"q12\": 0", "\"q12\": 1e150",
         "machine.control.osmc.q12 = 1e+150"},
        // The velocity has a range of its own (it was checked only once the mechanism closed).
        {"the crank's velocity", "quick_return_job.json", "\"velocity_m_s\": -0.762",
         "\"velocity_m_s\": 1e300",
         "machine.cut.velocity_m_s = 1e+300 m/s is outside [-10, -0.0001] m/s"},
        // A schema-1 file of the crank: the robot's keys every schema-1 job carried go, its own
        // stay and are checked (all were dropped: the default mechanism loaded silently).
        {"a schema-1 crank", "default_job.json", "\"machine\": \"pipe_robot_6axis\"",
         "\"machine\": \"quick_return_cutter\", \"mechanism\": {\"r2_m\": -5}",
         "machine.mechanism.r2_m = -5 m is outside"},
        // The saw's wall with an overcut past its own range: the wall still has its message.
        {"the saw's wall", "flying_saw_job.json", "\"wall_mm\": 2", "\"wall_mm\": -5",
         "machine.tube.wall_mm = -5 mm is outside [0.1, 500] mm"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.why);
        std::ifstream in(std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/" + c.job);
        std::stringstream ss;
        ss << in.rdbuf();
        std::string text = ss.str();
        const size_t at = text.find(c.from);
        ASSERT_NE(at, std::string::npos) << c.from;
        text.replace(at, std::string(c.from).size(), c.to);
        const fs::path file = dir / c.job;
        std::ofstream(file) << text;
        const Result r = runCli("validate " + file.string());
        EXPECT_EQ(r.code, 2) << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
    }
}

TEST(Cli, UnreachablePathExitsThreeNamingPointAndJoint) {
    const fs::path dir = tempDir("unreachable");
    Job job = defaultJob();
    cutcell::pipeRobotSpec(job).method = CutMethod::StaticPipe;
    job.cut.target = CutTarget::Branch;
    saveJobFile(job, (dir / "job.json").string());
    const Result r =
        runCli("plan " + (dir / "job.json").string() + " --out " + (dir / "out").string());
    EXPECT_EQ(r.code, 3) << r.output;
    EXPECT_NE(r.output.find("point "), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out" / "path.csv"));
}

// Issue 22: a job the machine cannot make (well-formed, refused by the plan) was reported "job
// ... is valid: ..." with exit 3. validate says it is refused, names the reason, exit 3 - the
// flying saw at twice the line speed its stroke allows, the pipe robot's unreachable branch
// cut, the section-steel cutter's torch that may not lean between an IPE 100's flanges.
TEST(Cli, ValidateNeverCallsARefusedJobValid) {
    const fs::path dir = tempDir("refused");
    const struct {
        const char* why;
        const char* job; // in resources/jobs, or "" for the pipe robot written below
        std::vector<std::pair<std::string, std::string>> edits;
        const char* reason;
    } cases[] = {
        {"the saw at 120 m/min",
         "flying_saw_job.json",
         {{"\"speed_m_min\": 60", "\"speed_m_min\": 120"}},
         "carriage.stroke_mm = 2500 mm is too short"},
        {"the robot's branch cut on a static pipe", "", {}, "path not reachable"},
        {"a torch that may not lean",
         "section_steel_job.json",
         {{"\"IPE 300\"", "\"IPE 100\""}, {"\"max_lean_deg\": 60", "\"max_lean_deg\": 0"}},
         "the torch body hits the section"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.why);
        const fs::path file = dir / (std::string(c.job).empty() ? "robot.json" : c.job);
        if (std::string(c.job).empty()) {
            Job job = defaultJob();
            cutcell::pipeRobotSpec(job).method = CutMethod::StaticPipe;
            job.cut.target = CutTarget::Branch;
            saveJobFile(job, file.string());
        } else {
            std::ifstream in(std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/" + c.job);
            std::stringstream ss;
            ss << in.rdbuf();
            std::string text = ss.str();
            for (const auto& [from, to] : c.edits) {
                const size_t at = text.find(from);
                ASSERT_NE(at, std::string::npos) << from;
                text.replace(at, from.size(), to);
            }
            std::ofstream(file) << text;
        }
        const Result r = runCli("validate " + file.string());
        EXPECT_EQ(r.code, 3) << r.output;
        EXPECT_EQ(r.output.find("is valid"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("is refused (not feasible)"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(c.reason), std::string::npos) << r.output;
    }
    // The shipped saw job still plans: valid, exit 0.
    const Result ok = runCli("validate " + std::string(CUTCELL_SOURCE_DIR) +
                             "/resources/jobs/flying_saw_job.json");
    EXPECT_EQ(ok.code, 0) << ok.output;
    EXPECT_NE(ok.output.find("is valid"), std::string::npos) << ok.output;
}

TEST(Cli, PlanWritesPathAndJointsCsv) {
    const fs::path dir = tempDir("plan");
    const Result r = runCli("plan " + defaultJobPath() + " --out " + dir.string());
    ASSERT_EQ(r.code, 0) << r.output;
    std::ifstream path(dir / "path.csv");
    std::string header;
    std::getline(path, header);
    EXPECT_EQ(header.rfind("index,t_s,s_mm,phi_deg,x_mm,y_mm,z_mm,", 0), 0u) << header;
    const Job job = defaultJob();
    std::string line;
    int rows = 0;
    while (std::getline(path, line)) {
        std::stringstream ss(line);
        std::string cell;
        std::vector<double> v;
        while (std::getline(ss, cell, ','))
            v.push_back(std::atof(cell.c_str()));
        // Main pipe frame: x^2 + y^2 = R1^2 (columns x_mm, y_mm).
        ASSERT_NEAR(std::hypot(v[4], v[5]), job.main_pipe.radius_mm, 1e-6) << line;
        ++rows;
    }
    EXPECT_GT(rows, 100);
    std::ifstream joints(dir / "joints.csv");
    std::getline(joints, header);
    EXPECT_EQ(header, "t_s,q0_deg,q1_deg,q2_deg,q3_deg,q4_deg,q5_deg");
    int jrows = 0;
    double lastT = -1;
    while (std::getline(joints, line)) {
        const double t = std::atof(line.c_str());
        ASSERT_NEAR(t - lastT, lastT < 0 ? t + 1 : job.sim.period_s, 1e-9);
        lastT = t;
        ++jrows;
    }
    // The whole cut at the control period, both ends included.
    const double cutTime = 0.001 * (jrows - 1);
    EXPECT_GE(cutTime, 30.0 - 1e-9);
    EXPECT_LT(cutTime, 30.0 + 0.01);
}

TEST(Cli, SimulateWritesTheReport) {
    const fs::path dir = tempDir("simulate");
    const Result r =
        runCli("simulate " + defaultJobPath() + " --report " + (dir / "report.json").string());
    ASSERT_EQ(r.code, 0) << r.output;
    const json::Value v = json::parse(readTextFile((dir / "report.json").string()));
    EXPECT_EQ(v.find("joints")->asArray().size(), 6u);
    EXPECT_TRUE(v.find("reachable")->asBool());
    EXPECT_EQ(v.find("method")->asString(), "rotating_pipe");
}

TEST(Cli, BenchPrintsTheFigures) {
    const Result r = runCli("bench --json --quick", false); // the JSON is on stdout
    ASSERT_EQ(r.code, 0) << r.output;
    const json::Value v = json::parse(r.output);
    EXPECT_GT(v.find("ik_ns_per_solve")->asNumber(), 0);
    EXPECT_GT(v.find("simulate_realtime_factor")->asNumber(), 0);
}

TEST(Cli, UnknownCommandAndMissingArgumentsAreUsageErrors) {
    EXPECT_EQ(runCli("frobnicate").code, 64);
    EXPECT_EQ(runCli("plan " + defaultJobPath()).code, 64);
    EXPECT_EQ(runCli("validate /nonexistent/job.json").code, 1);
}

// cutcell-cli fk / ik on the pipe robot: the pose of some joints, then every IK branch of
// that pose; the joints come back as an "ok" branch. Bad input names the option.
TEST(Cli, PipeRobotForwardThenInverseListsTheJoints) {
    const double q[5] = {20, 35, -25, 30, 10};
    const Result fk = runCli("fk " + defaultJobPath() + " --joints 20,35,-25,30,10", false);
    ASSERT_EQ(fk.code, 0) << fk.output;
    const json::Value f = json::parse(fk.output);
    const auto& tip = f.find("tip_mm")->asArray();
    const auto& torch = f.find("torch")->asArray();
    std::string pose;
    for (const auto* a : {&tip, &torch})
        for (const auto& v : *a)
            pose += (pose.empty() ? "" : ",") + formatC("%.17g", v.asNumber());
    const Result ik = runCli("ik " + defaultJobPath() + " --pose " + pose + ",10", false);
    ASSERT_EQ(ik.code, 0) << ik.output;
    const json::Value i = json::parse(ik.output);
    bool found = false;
    for (const auto& b : i.find("branches")->asArray()) {
        if (b.find("status")->asString() != "ok") continue;
        const auto& j = b.find("joints_deg")->asArray();
        double d = 0;
        for (size_t k = 0; k < 5; ++k)
            d += std::fabs(j[k].asNumber() - q[k]);
        found = found || d < 1e-6;
    }
    EXPECT_TRUE(found) << ik.output;
    const Result bad = runCli("fk " + defaultJobPath() + " --joints 1,2,3");
    EXPECT_EQ(bad.code, 64);
    EXPECT_NE(bad.output.find("--joints needs 5 values"), std::string::npos) << bad.output;
    const Result arm = runCli("ik " + defaultJobPath() + " --arm path --pose 1,2,3,0,0,1");
    EXPECT_EQ(arm.code, 64);
    EXPECT_NE(arm.output.find("--arm"), std::string::npos) << arm.output;
}

// cutcell-cli tune: prints the SIMC gains and touches no file without --out; --out writes the
// job with them (the rest of the job as it was), also over the job itself; a machine without
// tuning is a usage error, a cut that cannot be planned exit 3.
TEST(Cli, TunePrintsTheGainsAndWritesOnlyWhereTold) {
    const fs::path dir = tempDir("tune");
    const Job original = loadJobFile(defaultJobPath());
    const fs::path job = dir / "job.json";
    saveJobFile(original, job.string());
    const std::string before = readTextFile(job.string());

    const Result look = runCli("tune " + job.string());
    EXPECT_EQ(look.code, 0) << look.output;
    for (const char* s :
         {"chuck (theta0)", "theta5", "Kp", "tau_f", "integrating with lag", "not written"})
        EXPECT_NE(look.output.find(s), std::string::npos) << s << "\n" << look.output;
    EXPECT_EQ(readTextFile(job.string()), before);

    const PipeRobotTuning expected = tunePipeRobot(original);
    const fs::path out = dir / "tuned.json";
    const Result write = runCli("tune " + job.string() + " --out " + out.string());
    EXPECT_EQ(write.code, 0) << write.output;
    Job tuned = loadJobFile(out.string());
    for (size_t i = 0; i < kAxisCount; ++i) {
        const PidGains& g = pipeRobotSpec(tuned).controller[i];
        EXPECT_EQ(g.kp, expected.gains[i].kp) << i;
        EXPECT_EQ(g.ki, expected.gains[i].ki) << i;
        EXPECT_EQ(g.kd, expected.gains[i].kd) << i;
        EXPECT_EQ(g.tau_f, pipeRobotSpec(original).controller[i].tau_f) << i;
    }
    pipeRobotSpec(tuned).controller = pipeRobotSpec(original).controller;
    EXPECT_EQ(json::write(jobToJson(tuned)), json::write(jobToJson(original)));

    // A slower closed loop: smaller gains. Over the job itself.
    const Result smooth = runCli("tune " + job.string() + " --tau-c-ms 10 --out " + job.string());
    EXPECT_EQ(smooth.code, 0) << smooth.output;
    EXPECT_LT(pipeRobotSpec(loadJobFile(job.string())).controller[2].kp, expected.gains[2].kp);
    EXPECT_EQ(runCli("tune " + job.string() + " --tau-c-ms 0").code, 64);

    const Result saw =
        runCli("tune " + std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/flying_saw_job.json");
    EXPECT_EQ(saw.code, 64) << saw.output;
    EXPECT_NE(saw.output.find("has no controller tuning"), std::string::npos) << saw.output;

    Job unreachable = original;
    pipeRobotSpec(unreachable).method = CutMethod::StaticPipe;
    unreachable.cut.target = CutTarget::Branch;
    saveJobFile(unreachable, (dir / "far.json").string());
    const Result far = runCli("tune " + (dir / "far.json").string() + " --out " +
                              (dir / "far_tuned.json").string());
    EXPECT_EQ(far.code, 3) << far.output;
    EXPECT_FALSE(fs::exists(dir / "far_tuned.json"));
}

// cutcell-cli materials: the table listed, a row picked as the library picks it, a thickness
// outside the chart refused with the chart's range, a thickness with a decimal comma refused.
TEST(Cli, MaterialsListsTheChartsAndPicksARow) {
    const CutChartSet& set = shippedCutCharts();
    ASSERT_FALSE(set.charts.empty());
    const Result list = runCli("materials");
    EXPECT_EQ(list.code, 0) << list.output;
    for (const CutChart& c : set.charts)
        EXPECT_NE(list.output.find(c.name()), std::string::npos) << c.name();

    const CutChart& chart = set.charts.front();
    const double t =
        0.5 * (chart.rows[0].thicknessMm() + chart.rows[1].thicknessMm()); // between rows
    const std::string args =
        formatC("materials --json --pick %s %s '%s' %.17g", toString(chart.process),
                chart.material.c_str(), chart.consumable.c_str(), t);
    const Result picked = runCli(args, false);
    ASSERT_EQ(picked.code, 0) << picked.output;
    const json::Value doc = json::parse(picked.output);
    const CutPick expected = pickCutRow(chart, t);
    ASSERT_TRUE(expected.ok());
    for (CutFigure f : chart.columns) {
        const auto v = expected.row.get(f);
        ASSERT_TRUE(v.has_value());
        const json::Value* row = doc.find("row");
        ASSERT_NE(row, nullptr) << picked.output;
        const json::Value* value = row->find(cutFigureInfo(f).key);
        ASSERT_NE(value, nullptr) << cutFigureInfo(f).key;
        EXPECT_EQ(value->asNumber(), *v) << cutFigureInfo(f).key;
    }

    const double beyond = chart.rows.back().thicknessMm() + 1;
    const Result refused =
        runCli(formatC("materials --pick %s %s '%s' %g", toString(chart.process),
                       chart.material.c_str(), chart.consumable.c_str(), beyond));
    EXPECT_EQ(refused.code, 2) << refused.output;
    EXPECT_NE(refused.output.find("process.thickness_mm"), std::string::npos) << refused.output;
    EXPECT_NE(refused.output.find(formatC("%g .. %g mm", chart.rows.front().thicknessMm(),
                                          chart.rows.back().thicknessMm())),
              std::string::npos)
        << refused.output;

    const Result comma = runCli(formatC("materials --pick %s %s '%s' 2,5", toString(chart.process),
                                        chart.material.c_str(), chart.consumable.c_str()));
    EXPECT_EQ(comma.code, 64) << comma.output;
    const Result short_ = runCli("materials --pick plasma mild_steel");
    EXPECT_EQ(short_.code, 64) << short_.output;
    EXPECT_NE(short_.output.find("takes 4 values"), std::string::npos) << short_.output;
    EXPECT_EQ(runCli("materials --file /nonexistent/charts.json").code, 1);
    const Result folder = runCli("materials --file " + std::string(CUTCELL_SOURCE_DIR));
    EXPECT_EQ(folder.code, 1) << folder.output;
    EXPECT_NE(folder.output.find("it is a folder"), std::string::npos) << folder.output;
}

// cutcell-cli materials edits the user's table ($XDG_DATA_HOME/cutcell/cut_charts.json, a copy
// of the shipped one at the first edit, used from then on) or --file, numbers in C notation
// under a decimal-comma locale; a refused edit names the chart, row, field, value, unit and
// limit (exit 2) and leaves the file alone; a number with a comma is a usage error (exit 64).
TEST(Cli, MaterialsEditsTheUserTableUnderADecimalCommaLocale) {
    const fs::path dir = tempDir("materials_edit");
    struct Env {
        std::string name, was;
        bool had;
        Env(const char* n, const std::string& value) : name(n) {
            const char* v = std::getenv(n);
            had = v != nullptr;
            was = v ? v : "";
            ::setenv(n, value.c_str(), 1);
        }
        ~Env() {
            if (had)
                ::setenv(name.c_str(), was.c_str(), 1);
            else
                ::unsetenv(name.c_str());
        }
    };
    const Env xdg("XDG_DATA_HOME", dir.string());
    const Env lc("LC_ALL", "de_DE.UTF-8");
    const fs::path user = dir / "cutcell" / "cut_charts.json";
    const CutChart& chart = shippedCutCharts().charts.front();
    const std::string c = formatC("%s %s '%s'", toString(chart.process), chart.material.c_str(),
                                  chart.consumable.c_str());
    const double t = chart.rows[1].thicknessMm();
    const std::string at = c + formatC(" %g", t);

    const Result list = runCli("materials");
    EXPECT_EQ(list.code, 0) << list.output;
    EXPECT_NE(list.output.find("the shipped table"), std::string::npos) << list.output;
    EXPECT_FALSE(fs::exists(user));

    const Result set = runCli("materials --set " + at + " cut_speed_mm_min 1234.5");
    ASSERT_EQ(set.code, 0) << set.output;
    EXPECT_NE(set.output.find(user.string()), std::string::npos) << set.output;
    CutChartSet expected = shippedCutCharts();
    expected.charts[0].rows[1].set(CutFigure::CutSpeedMmMin, 1234.5);
    EXPECT_EQ(loadCutChartsFile(user.string()), expected);
    // The user's table is the one in use now.
    const Result picked = runCli("materials --json --pick " + at, false);
    ASSERT_EQ(picked.code, 0) << picked.output;
    EXPECT_EQ(json::parse(picked.output).find("row")->find("cut_speed_mm_min")->asNumber(), 1234.5);

    // Refused: out of range (named), a comma, an unknown figure, a row that is not there.
    const std::string before = [&] {
        std::ifstream in(user);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }();
    const Result far = runCli("materials --set " + at + " cut_speed_mm_min 200000");
    EXPECT_EQ(far.code, 2) << far.output;
    EXPECT_NE(far.output.find("(charts[0]) rows[1]: cut_speed_mm_min = 200000 mm/min is outside "
                              "(0, 100000] mm/min"),
              std::string::npos)
        << far.output;
    EXPECT_EQ(runCli("materials --set " + at + " cut_speed_mm_min 1234,5").code, 64);
    EXPECT_EQ(runCli("materials --set " + at + " speed 1").code, 64);
    const Result none = runCli("materials --set " + c + " 0.77 cut_speed_mm_min 1");
    EXPECT_EQ(none.code, 2) << none.output;
    EXPECT_NE(none.output.find("no row at thickness_mm = 0.77 mm"), std::string::npos)
        << none.output;
    std::ifstream again(user);
    std::stringstream now;
    now << again.rdbuf();
    EXPECT_EQ(now.str(), before);

    // Add a row between the first two (every column), then remove it.
    const double mid = 0.5 * (chart.rows[0].thicknessMm() + t);
    std::string figures;
    for (CutFigure f : chart.columns)
        if (f != CutFigure::ThicknessMm)
            figures += formatC(" %s=%g", cutFigureInfo(f).key, *chart.rows[0].get(f));
    const Result added = runCli("materials --add-row " + c + formatC(" %g", mid) + figures);
    ASSERT_EQ(added.code, 0) << added.output;
    CutChartSet withRow = loadCutChartsFile(user.string());
    ASSERT_EQ(withRow.charts[0].rows.size(), chart.rows.size() + 1);
    EXPECT_EQ(withRow.charts[0].rows[1].thicknessMm(), mid);
    const Result twice = runCli("materials --add-row " + c + formatC(" %g", mid) + figures);
    EXPECT_EQ(twice.code, 2) << twice.output;
    EXPECT_NE(twice.output.find("has a row already"), std::string::npos) << twice.output;
    const Result removed = runCli("materials --remove-row " + c + formatC(" %g", mid));
    ASSERT_EQ(removed.code, 0) << removed.output;
    EXPECT_EQ(loadCutChartsFile(user.string()), expected);
    // No temporary file beside the table.
    for (const auto& e : fs::directory_iterator(user.parent_path()))
        EXPECT_EQ(e.path().filename(), "cut_charts.json") << e.path();

    // --file edits that file and leaves the user's table alone.
    const fs::path other = dir / "other.json";
    std::ofstream(other) << writeCutCharts(shippedCutCharts());
    const Result file =
        runCli("materials --file " + other.string() + " --set " + at + " cut_speed_mm_min 999.5");
    ASSERT_EQ(file.code, 0) << file.output;
    EXPECT_EQ(*loadCutChartsFile(other.string()).charts[0].rows[1].get(CutFigure::CutSpeedMmMin),
              999.5);
    EXPECT_EQ(loadCutChartsFile(user.string()), expected);
    EXPECT_EQ(runCli("materials --pick " + at + " --set " + at + " kerf_mm 1").code, 64);
    fs::remove_all(dir);
}
