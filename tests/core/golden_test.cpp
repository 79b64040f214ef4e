// The outputs of the shipped jobs must not change when the code is restructured: the CLI
// regenerates them and they are compared with the files captured before the machine modules
// (robot, profile cutter) and before the run model and field tables (the other three machines;
// tests/data/golden/). Numbers must agree to 1e-9 relative, all other text exactly, except
// the documented schema line (README, "Golden files").
//
// CUTCELL_WRITE_GOLDENS=1 writes the files instead of comparing (only when the outputs are
// meant to change; say why in the commit).
#include <gtest/gtest.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kSource = CUTCELL_SOURCE_DIR;
const fs::path kGolden = kSource / "tests/data/golden";

std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

int runCli(const std::string& args) {
    const std::string cmd = std::string(CUTCELL_CLI) + " " + args + " >/dev/null 2>&1";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The robot's golden input: the default job as it was before the rigid-body plant (its gains,
// one linear plant per joint, "plant_model": "linear"). The linear plant's outputs must not
// change; the rigid-body plant is checked by its own tests.
const fs::path kRobotJob = kSource / "tests/data/golden/robot_linear_job.json";

// The robot's golden job with its method replaced (plan has no --method option).
fs::path jobWithMethod(const fs::path& dir, const std::string& method) {
    std::string text = readAll(kRobotJob);
    const std::string from = "\"method\": \"rotating_pipe\"";
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos);
    if (at != std::string::npos) text.replace(at, from.size(), "\"method\": \"" + method + "\"");
    const fs::path p = dir / ("default_" + method + ".json");
    std::ofstream(p) << text;
    return p;
}

// Writes every golden output into dir (relative names as under tests/data/golden).
std::vector<std::string> generate(const fs::path& dir) {
    const std::string defaultJob = kRobotJob.string();
    const std::string profileJob = (kSource / "resources/jobs/profile_cutter_job.json").string();
    for (const std::string method : {"static_pipe", "rotating_pipe"}) {
        const fs::path job = jobWithMethod(dir, method);
        EXPECT_EQ(runCli("plan " + job.string() + " --out " + (dir / ("robot_" + method)).string()),
                  0)
            << method;
        EXPECT_EQ(runCli("simulate " + defaultJob + " --method " + method + " --report " +
                         (dir / ("robot_" + method + "_report.json")).string()),
                  0)
            << method;
    }
    EXPECT_EQ(runCli("plan " + profileJob + " --out " + (dir / "profile").string()), 0);
    EXPECT_EQ(runCli("export " + profileJob + " --gcode " + (dir / "profile/cut.ngc").string() +
                     " --template-svg " + (dir / "profile/template.svg").string()),
              0);
    // The other three machines' shipped jobs (captured with the CLI of cb459ff, before the
    // machine-neutral run model and the field tables).
    for (const std::string m : {"flying_saw", "quick_return", "section_steel"})
        EXPECT_EQ(runCli("plan " + (kSource / ("resources/jobs/" + m + "_job.json")).string() +
                         " --out " + (dir / m).string()),
                  0)
            << m;
    for (const std::string m : {"flying_saw", "quick_return"})
        EXPECT_EQ(runCli("simulate " + (kSource / ("resources/jobs/" + m + "_job.json")).string() +
                         " --report " + (dir / (m + "_report.json")).string()),
                  0)
            << m;
    return {"robot_static_pipe/path.csv",
            "robot_static_pipe/joints.csv",
            "robot_rotating_pipe/path.csv",
            "robot_rotating_pipe/joints.csv",
            "robot_static_pipe_report.json",
            "robot_rotating_pipe_report.json",
            "profile/path.csv",
            "profile/cut.ngc",
            "profile/template.svg",
            "flying_saw/cam.csv",
            "flying_saw/cycle.csv",
            "flying_saw/pieces.csv",
            "flying_saw_report.json",
            "quick_return/quick_return.json",
            "quick_return/quick_return_cut.svg",
            "quick_return_report.json",
            "section_steel/path.csv"};
}

// Splits text into numbers and the text between them.
struct Token {
    bool number;
    std::string text;
    double value;
};

std::vector<Token> tokenize(const std::string& s) {
    std::vector<Token> out;
    size_t i = 0;
    std::string textRun;
    while (i < s.size()) {
        // A digit inside a name ("q0_deg", "X575.7") starts a number too: the text around it
        // still has to match exactly.
        const bool startsNumber = std::isdigit(static_cast<unsigned char>(s[i])) ||
                                  ((s[i] == '-' || s[i] == '.') && i + 1 < s.size() &&
                                   std::isdigit(static_cast<unsigned char>(s[i + 1])));
        if (startsNumber) {
            double v = 0;
            const auto r = std::from_chars(s.data() + i, s.data() + s.size(), v);
            if (r.ec == std::errc() && r.ptr > s.data() + i) {
                out.push_back({false, textRun, 0});
                textRun.clear();
                out.push_back({true, std::string(s.data() + i, r.ptr), v});
                i = static_cast<size_t>(r.ptr - s.data());
                continue;
            }
        }
        textRun += s[i++];
    }
    out.push_back({false, textRun, 0});
    return out;
}

bool isSchemaLine(const std::string& line) {
    return line.find("\"schema\"") != std::string::npos;
}

// Drops the documented schema line (a JSON member "schema": N) from both sides.
std::string withoutSchemaLines(const std::string& s) {
    std::stringstream in(s);
    std::string out, line;
    while (std::getline(in, line))
        if (!isSchemaLine(line)) out += line + "\n";
    return out;
}

// Empty when equal; else where and how they differ.
std::string compare(const std::string& expectedText, const std::string& actualText) {
    const auto e = tokenize(withoutSchemaLines(expectedText));
    const auto a = tokenize(withoutSchemaLines(actualText));
    if (e.size() != a.size())
        return "token count " + std::to_string(a.size()) + " != golden " + std::to_string(e.size());
    for (size_t k = 0; k < e.size(); ++k) {
        if (e[k].number != a[k].number) return "token " + std::to_string(k) + " kind differs";
        if (!e[k].number) {
            if (e[k].text != a[k].text)
                return "text differs at token " + std::to_string(k) + ": \"" + a[k].text +
                       "\" != golden \"" + e[k].text + "\"";
            continue;
        }
        const double x = e[k].value, y = a[k].value;
        const double tol = 1e-9 * std::max(std::fabs(x), std::fabs(y));
        if (!(std::fabs(x - y) <= tol))
            return "number differs at token " + std::to_string(k) + ": " + a[k].text +
                   " != golden " + e[k].text;
    }
    return {};
}

} // namespace

TEST(GoldenCompare, TokenizerSeesNumbersAndText) {
    EXPECT_EQ(compare("a,1.5,X2\n", "a,1.5000000000001,X2\n"), "");
    EXPECT_NE(compare("a,1.5\n", "a,1.6\n"), "");
    EXPECT_NE(compare("a,1.5\n", "b,1.5\n"), "");
    EXPECT_NE(compare("1,5\n", "1.5\n"), ""); // a decimal comma is a different text
    EXPECT_EQ(
        compare("{\n  \"schema\": 1,\n  \"x\": 2\n}\n", "{\n  \"schema\": 2,\n  \"x\": 2\n}\n"),
        "");
}

TEST(Golden, ShippedJobsGiveTheCapturedOutputs) {
    const fs::path dir =
        fs::temp_directory_path() / ("cutcell_golden_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const auto files = generate(dir);
    const bool write = std::getenv("CUTCELL_WRITE_GOLDENS") != nullptr;
    for (const auto& f : files) {
        SCOPED_TRACE(f);
        ASSERT_TRUE(fs::exists(dir / f));
        if (write) {
            fs::create_directories((kGolden / f).parent_path());
            fs::copy_file(dir / f, kGolden / f, fs::copy_options::overwrite_existing);
            continue;
        }
        ASSERT_TRUE(fs::exists(kGolden / f));
        EXPECT_EQ(compare(readAll(kGolden / f), readAll(dir / f)), "");
    }
}
