// The command line of cutcell-cli (CLI11): every command's help and options, unknown and
// misspelt options, missing or bad arguments, value ranges, and numbers read the same under a
// German locale. Runs the built binary as a user does, plus the option checks in-process.
#include "app/cli/option_checks.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/machine_registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

struct Result {
    int code;
    std::string out; // stdout
    std::string all; // stdout + stderr
};

// `env` is prepended to the command line (e.g. "LC_ALL=de_DE.UTF-8").
Result runCli(const std::string& args, const std::string& env = "") {
    const fs::path err =
        fs::temp_directory_path() / ("cutcell_cli_options_err_" + std::to_string(::getpid()));
    const std::string cmd =
        env + " " + std::string(CUTCELL_CLI) + " " + args + " 2>" + err.string();
    FILE* p = ::popen(cmd.c_str(), "r");
    Result r{-1, {}, {}};
    char buf[4096];
    while (p && std::fgets(buf, sizeof buf, p))
        r.out += buf;
    const int status = p ? ::pclose(p) : -1;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(err);
    r.all = r.out + std::string(std::istreambuf_iterator<char>(in), {});
    fs::remove(err);
    return r;
}

std::string defaultJob() {
    return std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/default_job.json";
}

// Where the refused calls would have written: must stay empty.
fs::path refusedDir() {
    return fs::temp_directory_path() / "cutcell_cli_options_refused";
}

fs::path tempDir(const std::string& name) {
    const fs::path d = fs::temp_directory_path() / ("cutcell_cli_options_" + name);
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// Every command with its options as the help must show them, and the arguments that make a
// valid call (so that an added unknown option is the only fault).
struct CommandSpec {
    std::string name;
    std::vector<std::string> options;
    std::string validArgs;
};

std::vector<CommandSpec> commands() {
    const std::string job = defaultJob();
    const std::vector<std::string> drives{"--devices",   "--can-plugin", "--can-interface",
                                          "--period-ms", "--clock",      "--drivesim"};
    std::vector<std::string> simulate{"--report", "--method"};
    simulate.insert(simulate.end(), drives.begin(), drives.end());
    std::vector<CommandSpec> list{
        {"validate", {}, job},
        {"plan", {"--out"}, job + " --out " + (refusedDir() / "out").string()},
        {"simulate", simulate, job},
        {"bench", {"--json", "--quick", "--job", "--no-engine", "--no-can"}, "--quick"},
        {"export",
         {"--gcode", "--template-svg", "--template-pdf", "--path-csv", "--joints-csv", "--paper"},
         job + " --template-svg " + (refusedDir() / "t.svg").string()},
        {"machines", {"--json"}, "--json"},
        {"upgrade", {"--out"}, job + " --out " + (refusedDir() / "new.json").string()},
        {"import-dstv",
         {"--out"},
         std::string(CUTCELL_SOURCE_DIR) + "/tests/data/dstv/ipe300_square.nc1 --out " +
             (refusedDir() / "imported.json").string()},
    };
#ifdef CUTCELL_CLI_HAS_DEVICES
    std::vector<std::string> run{"--realtime", "--quiet", "--report", "--runs"};
    run.insert(run.end(), drives.begin(), drives.end());
    list.push_back({"run", run, job});
    list.push_back(
        {"drivesim",
         {"--nodes", "--plugin", "--interface", "--duration", "--fault-node", "--fault-code",
          "--fault-after", "--heartbeat-stop-after", "--following-error-after"},
         "--nodes 1-6 --duration 1"});
#endif
    return list;
}

} // namespace

TEST(CliOptions, TopLevelHelpListsEveryCommand) {
    for (const std::string help : {"--help", "-h", "help"}) {
        const Result r = runCli(help);
        EXPECT_EQ(r.code, 0) << help << "\n" << r.all;
        for (const CommandSpec& c : commands())
            EXPECT_TRUE(contains(r.out, "\n  " + c.name + " ")) << c.name << "\n" << r.out;
        EXPECT_TRUE(contains(r.out, "64 usage")) << r.out;
    }
    // No command at all: the same list on stderr, and a usage error.
    const Result none = runCli("");
    EXPECT_EQ(none.code, 64);
    EXPECT_TRUE(none.out.empty()) << none.out;
    EXPECT_TRUE(contains(none.all, "validate")) << none.all;
}

TEST(CliOptions, EveryCommandHasHelpNamingItsOptions) {
    for (const CommandSpec& c : commands()) {
        for (const std::string& args : {c.name + " --help", "help " + c.name}) {
            const Result r = runCli(args);
            EXPECT_EQ(r.code, 0) << args << "\n" << r.all;
            EXPECT_TRUE(contains(r.out, "Usage: cutcell-cli " + c.name)) << args << "\n" << r.out;
            for (const std::string& option : c.options)
                EXPECT_TRUE(contains(r.out, option + " ")) << args << ": " << option << "\n"
                                                           << r.out;
        }
    }
}

TEST(CliOptions, EveryCommandRefusesAnUnknownOptionNamingIt) {
    fs::remove_all(refusedDir());
    fs::create_directories(refusedDir());
    for (const CommandSpec& c : commands()) {
        for (const std::string bad : {"--no-such-option", "--no-such-option=3", "-Z"}) {
            const Result r = runCli(c.name + " " + c.validArgs + " " + bad, "timeout 60");
            EXPECT_EQ(r.code, 64) << c.name << " " << bad << "\n" << r.all;
            const std::string named = bad.substr(0, bad.find('='));
            EXPECT_TRUE(contains(r.all, "unknown option " + named)) << c.name << "\n" << r.all;
            EXPECT_TRUE(contains(r.all, "cutcell-cli " + c.name)) << r.all;
        }
    }
    // Nothing was written by the refused calls.
    EXPECT_TRUE(fs::is_empty(refusedDir()));
    const Result top = runCli("--verbose");
    EXPECT_EQ(top.code, 64) << top.all;
    EXPECT_TRUE(contains(top.all, "--verbose")) << top.all;
    const Result unknown = runCli("frobnicate");
    EXPECT_EQ(unknown.code, 64) << unknown.all;
    EXPECT_TRUE(contains(unknown.all, "unknown command 'frobnicate'")) << unknown.all;
}

TEST(CliOptions, MisspeltFlagsAreRefusedWithTheNearestOption) {
    const std::string job = defaultJob();
    const std::map<std::string, std::string> misspelt{
        {"simulate " + job + " --reprot x.json", "--reprot (did you mean --report?)"},
        {"simulate " + job + " --method=static_pipe --devices simulated --perod-ms 2",
         "--perod-ms (did you mean --period-ms?)"},
        {"bench --quick --jsn", "--jsn (did you mean --json?)"},
        {"export " + job + " --gcod x.ngc", "--gcod (did you mean --gcode?)"},
#ifdef CUTCELL_CLI_HAS_DEVICES
        {"run " + job + " --quite", "--quite (did you mean --quiet?)"},
        {"drivesim --node 1-6", "--node (did you mean --nodes?)"},
#endif
    };
    for (const auto& [args, message] : misspelt) {
        const Result r = runCli(args);
        EXPECT_EQ(r.code, 64) << args << "\n" << r.all;
        EXPECT_TRUE(contains(r.all, "unknown option " + message)) << args << "\n" << r.all;
    }
}

TEST(CliOptions, MissingOrBadJobGivesItsExitCode) {
    const fs::path dir = tempDir("jobs");
    const std::string missing = (dir / "missing.json").string();
    const std::string broken = (dir / "broken.json").string();
    std::ofstream(broken) << "{ \"schema\": 1, \"main_pipe\": ";
    const std::string out = " --out " + (dir / "out").string();
    const std::string svg = " --template-svg " + (dir / "t.svg").string();
    const std::string upgraded = " --out " + (dir / "new.json").string();
    std::vector<std::pair<std::string, std::string>> needJob{{"validate", ""}, {"plan", out},
                                                             {"simulate", ""}, {"export", svg},
                                                             {"upgrade", upgraded}};
#ifdef CUTCELL_CLI_HAS_DEVICES
    needJob.push_back({"run", ""});
#endif
    for (const auto& [cmd, rest] : needJob) {
        const Result none = runCli(cmd + rest);
        EXPECT_EQ(none.code, 64) << cmd << "\n" << none.all;
        EXPECT_TRUE(contains(none.all, "JOB is required")) << cmd << "\n" << none.all;
        EXPECT_EQ(runCli(cmd + " " + missing + rest).code, 1) << cmd;
        EXPECT_EQ(runCli(cmd + " " + broken + rest).code, 2) << cmd;
    }
    EXPECT_FALSE(fs::exists(dir / "out"));
    EXPECT_FALSE(fs::exists(dir / "t.svg"));
    EXPECT_FALSE(fs::exists(dir / "new.json"));
    const Result upgradeNoOut = runCli("upgrade " + defaultJob());
    EXPECT_EQ(upgradeNoOut.code, 64);
    EXPECT_TRUE(contains(upgradeNoOut.all, "--out is required")) << upgradeNoOut.all;
    const Result noOut = runCli("plan " + defaultJob());
    EXPECT_EQ(noOut.code, 64);
    EXPECT_TRUE(contains(noOut.all, "--out is required")) << noOut.all;
    EXPECT_EQ(runCli("bench --job " + broken).code, 2);
    EXPECT_EQ(runCli("bench --job " + missing).code, 1);
#ifdef CUTCELL_CLI_HAS_DEVICES
    EXPECT_EQ(runCli("drivesim " + broken).code, 2);
    EXPECT_EQ(runCli("drivesim " + missing).code, 1);
#endif
    EXPECT_EQ(runCli("validate " + defaultJob() + " " + defaultJob()).code, 64);
}

TEST(CliOptions, ValuesOutsideTheirRangeNameOptionValueUnitAndLimit) {
    const std::string sim = "simulate " + defaultJob() + " --devices canopen";
    std::map<std::string, std::string> bad{
        {sim + " --period-ms 0.05", "--period-ms = \"0.05\" ms is outside [0.1, 100] ms"},
        {sim + " --period-ms 101", "--period-ms = \"101\" ms is outside [0.1, 100] ms"},
        {sim + " --period-ms 2,5", "--period-ms = \"2,5\" is not a number in [0.1, 100] ms"},
        {sim + " --period-ms nan", "--period-ms = \"nan\" is not a number"},
        {sim + " --period-ms", "--period-ms"},
        {sim + " --clock slow", "--clock = \"slow\" is not one of \"realtime\", \"fast\""},
        {"simulate " + defaultJob() + " --devices cann",
         "--devices = \"cann\" is not one of \"simulated\", \"canopen\""},
        {"simulate " + defaultJob() + " --method diagonal",
         "--method = \"diagonal\" is not one of \"static_pipe\", \"rotating_pipe\""},
        {"export " + defaultJob() + " --template-pdf t.pdf --paper A5",
         "--paper = \"A5\" is not one of \"single\", \"A4\", \"A3\""},
    };
#ifdef CUTCELL_CLI_HAS_DEVICES
    const std::map<std::string, std::string> drivesim{
        {"--nodes 0-200", "--nodes = \"0-200\": \"0-200\" is not a node id or range within 1..127"},
        {"--nodes 3-1", "--nodes = \"3-1\""},
        {"--nodes 1,,2", "--nodes = \"1,,2\": \"\" is not a node id"},
        {"--duration -1", "--duration = \"-1\" s is outside [0, 1e+06] s"},
        {"--fault-after 2e6", "--fault-after = \"2e6\" s is outside [0, 1e+06] s"},
        {"--heartbeat-stop-after x", "--heartbeat-stop-after = \"x\" is not a number"},
        {"--following-error-after -0.5", "--following-error-after = \"-0.5\" s is outside"},
        {"--fault-node 0", "--fault-node = \"0\" is outside [1, 127]"},
        {"--fault-node 2.5", "--fault-node = \"2.5\" is not a whole number in [1, 127]"},
        {"--fault-code 0", "--fault-code = \"0\" is not an EMCY code in 0x0001..0xFFFF"},
        {"--fault-code 0x10000", "--fault-code = \"0x10000\" is not an EMCY code"},
        {"--fault-code 0x23g0", "--fault-code = \"0x23g0\" is not an EMCY code"},
        {"--nodes 1-2 --fault-node 5", "--fault-node = 5 is not one of the simulated nodes"},
    };
    for (const auto& [args, message] : drivesim)
        bad.emplace("drivesim " + args, message);
#endif
    for (const auto& [args, message] : bad) {
        const Result r = runCli(args, "timeout 60"); // a value taken by mistake would run on
        EXPECT_EQ(r.code, 64) << args << "\n" << r.all;
        EXPECT_TRUE(contains(r.all, message)) << args << "\n" << r.all;
    }
}

TEST(CliOptions, OptionsTakeTheirValueWithEqualsSignAndUnderAGermanLocale) {
    const fs::path dir = tempDir("accepted");
    // --name=VALUE as well as --name VALUE; a CANopen-only override is accepted (and unused)
    // with simulated drives, as before.
    const Result plan = runCli("plan " + defaultJob() + " --out=" + (dir / "plan").string());
    EXPECT_EQ(plan.code, 0) << plan.all;
    EXPECT_TRUE(fs::exists(dir / "plan" / "path.csv"));
    const std::string report = (dir / "report.json").string();
    const std::string german = "LC_ALL=de_DE.UTF-8";
    const Result r = runCli("simulate " + defaultJob() +
                                " --method static_pipe --devices "
                                "simulated --period-ms 2.5 --clock=fast --report " +
                                report,
                            german);
    EXPECT_EQ(r.code, 0) << r.all;
    EXPECT_TRUE(fs::exists(report));
    EXPECT_EQ(
        runCli("simulate " + defaultJob() + " --devices canopen --period-ms 2,5", german).code, 64);
    // Given twice, the later value counts (a script appends its overrides).
    const std::string twice = (dir / "twice.json").string();
    const Result t = runCli("simulate " + defaultJob() +
                            " --method rotating_pipe --method static_pipe --report " + twice);
    EXPECT_EQ(t.code, 0) << t.all;
    std::ifstream in(twice);
    const std::string text{std::istreambuf_iterator<char>(in), {}};
    EXPECT_TRUE(contains(text, "\"method\": \"static_pipe\"")) << text.substr(0, 200);
}

// The parser reads numbers in C notation even after the process has taken a decimal-comma
// locale (as Qt does when the CAN commands create their QCoreApplication).
TEST(CliOptions, NumbersReadTheSameUnderAGermanLocale) {
    if (!std::setlocale(LC_ALL, "de_DE.UTF-8"))
        GTEST_SKIP() << "locale de_DE.UTF-8 not installed (localedef -i de_DE -f UTF-8 "
                        "de_DE.UTF-8)";
    EXPECT_EQ(std::strtod("2,5", nullptr), 2.5) << "the locale reads a decimal comma";
    double periodMs = 0;
    std::optional<int> node;
    CLI::App app("test");
    cutcell::cli::addNumber(app, "--period-ms", periodMs, {0.1, 100, "ms"}, "period");
    cutcell::cli::addInteger(app, "--fault-node", node, {1, 127, ""}, "node");
    EXPECT_NO_THROW(app.parse("--period-ms 2.5 --fault-node 12", false));
    EXPECT_EQ(periodMs, 2.5);
    EXPECT_EQ(node.value_or(0), 12);
    EXPECT_THROW(app.parse("--period-ms 2,5", false), CLI::ValidationError);
    std::setlocale(LC_ALL, "C");
}

TEST(CliOptions, NodeListsExpandRangesAndLists) {
    std::vector<int> ids;
    std::string error;
    ASSERT_TRUE(cutcell::cli::parseNodeList("2-3,7,1-1", ids, error)) << error;
    EXPECT_EQ(ids, (std::vector<int>{2, 3, 7, 1}));
    for (const char* bad : {"", "0", "128", "5-4", "1-", "a", "1;2", "1,"}) {
        ids.clear();
        EXPECT_FALSE(cutcell::cli::parseNodeList(bad, ids, error)) << bad;
    }
}

// `machines --json` lists every registered machine as the registry describes it: axes with
// name, unit, limits (of the machine's default job) and command mode, and its exports; the
// machines of both shipped jobs are among them.
TEST(CliMachines, JsonListsEveryRegisteredMachineWithAxesAndUnits) {
    const Result r = runCli("machines --json");
    ASSERT_EQ(r.code, 0) << r.all;
    const cutcell::json::Value doc = cutcell::json::parse(r.out);
    const cutcell::json::Value* list = doc.find("machines");
    ASSERT_TRUE(list && list->isArray()) << r.out;
    const auto registered = cutcell::machines();
    ASSERT_EQ(list->asArray().size(), registered.size());
    std::vector<std::string> ids;
    for (size_t i = 0; i < registered.size(); ++i) {
        const cutcell::MachineModule& m = *registered[i];
        const cutcell::json::Value& e = list->asArray()[i];
        ASSERT_TRUE(e.find("id") && e.find("title") && e.find("axes") && e.find("exports"));
        EXPECT_EQ(e.find("id")->asString(), m.id());
        EXPECT_EQ(e.find("title")->asString(), m.title());
        ids.push_back(e.find("id")->asString());
        const auto axes = m.axes(m.defaultJob());
        ASSERT_FALSE(axes.empty()) << m.id();
        const auto& jsonAxes = e.find("axes")->asArray();
        ASSERT_EQ(jsonAxes.size(), axes.size()) << m.id();
        for (size_t k = 0; k < axes.size(); ++k) {
            const cutcell::json::Value& a = jsonAxes[k];
            EXPECT_EQ(a.find("name")->asString(), axes[k].name);
            const std::string unit = a.find("unit")->asString();
            EXPECT_TRUE(unit == "deg" || unit == "mm") << unit;
            EXPECT_EQ(unit, cutcell::unitSymbol(axes[k].unit));
            EXPECT_EQ(a.find("min")->asNumber(), axes[k].min);
            EXPECT_EQ(a.find("max")->asNumber(), axes[k].max);
            EXPECT_LT(a.find("min")->asNumber(), a.find("max")->asNumber());
            EXPECT_EQ(a.find("command_mode")->asString(), cutcell::commandModeName(axes[k].mode));
        }
        const auto exports = m.exports();
        ASSERT_EQ(e.find("exports")->asArray().size(), exports.size()) << m.id();
        for (size_t k = 0; k < exports.size(); ++k)
            EXPECT_EQ(e.find("exports")->asArray()[k].find("id")->asString(), exports[k].id);
    }
    for (const char* shipped : {"default_job.json", "profile_cutter_job.json"}) {
        const cutcell::Job job = cutcell::loadJobFile(std::string(CUTCELL_SOURCE_DIR) +
                                                      "/resources/jobs/" + shipped);
        EXPECT_NE(std::find(ids.begin(), ids.end(), job.machine), ids.end()) << job.machine;
    }
    // The text listing names the same machines.
    const Result text = runCli("machines");
    EXPECT_EQ(text.code, 0) << text.all;
    for (const std::string& id : ids)
        EXPECT_TRUE(contains(text.out, id + ": ")) << text.out;
}

// `upgrade` writes the schema-2 file of a schema-1 job: it loads to the same job, and a second
// upgrade changes nothing; a job out of range is refused (exit 2) and nothing is written.
TEST(CliUpgrade, WritesASchema2FileThatLoadsToTheSameJob) {
    const fs::path dir = tempDir("upgrade");
    for (const char* shipped : {"default_job.json", "profile_cutter_job.json"}) {
        const std::string old = std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/" + shipped;
        const fs::path out = dir / (std::string("v2_") + shipped);
        const Result r = runCli("upgrade " + old + " --out " + out.string());
        ASSERT_EQ(r.code, 0) << r.all;
        const std::string text = cutcell::readTextFile(out.string());
        EXPECT_EQ(cutcell::json::parse(text).find("schema")->asNumber(), 2);
        EXPECT_EQ(cutcell::json::write(cutcell::jobToJson(cutcell::loadJobFile(out.string()))),
                  cutcell::json::write(cutcell::jobToJson(cutcell::loadJobFile(old))));
        const fs::path again = dir / (std::string("v2v2_") + shipped);
        ASSERT_EQ(runCli("upgrade " + out.string() + " --out " + again.string()).code, 0);
        EXPECT_EQ(cutcell::readTextFile(again.string()), text);
    }
    // Valid JSON and keys, a value out of range: exit 2, no file.
    std::string text = cutcell::readTextFile(defaultJob());
    const std::string key = "\"speed_mm_s\": ";
    const size_t at = text.find(key);
    ASSERT_NE(at, std::string::npos);
    text.insert(at + key.size(), "-");
    const fs::path bad = dir / "negative_speed.json";
    std::ofstream(bad) << text;
    const Result r = runCli("upgrade " + bad.string() + " --out " + (dir / "bad_v2.json").string());
    EXPECT_EQ(r.code, 2) << r.all;
    EXPECT_TRUE(contains(r.all, "speed_mm_s")) << r.all;
    EXPECT_FALSE(fs::exists(dir / "bad_v2.json"));
}
