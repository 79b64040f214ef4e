// DSTV (NC1) import of the section-steel cutter: hand-written files in tests/data/dstv/ for
// each block type (ST, AK, IK, BO, SI, EN and a block not interpreted) are imported with their
// report lines, broken ones (unknown block, truncated header, bad numbers, missing EN) and
// pieces the cutter cannot take are refused naming the line; the CLI command import-dstv under
// a decimal-comma locale writes the same job.
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/job_importer.h"
#include "core/machines/section_steel/dstv/dstv_import.h"
#include "core/machines/section_steel/dstv/dstv_reader.h"
#include "core/machines/section_steel/section_steel_spec.h"

#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace cutcell;
using namespace cutcell::section_steel;

namespace {

std::string dataPath(const std::string& name) {
    return std::string(CUTCELL_SOURCE_DIR) + "/tests/data/dstv/" + name;
}

std::string data(const std::string& name) {
    return readTextFile(dataPath(name));
}

const SectionSteelSpec& specOf(const Job& job) {
    return *job.machine_spec.as<SectionSteelSpec>();
}

bool hasLine(const std::vector<std::string>& report, const std::string& prefix,
             const std::string& part) {
    for (const std::string& l : report)
        if (l.rfind(prefix, 0) == 0 && l.find(part) != std::string::npos) return true;
    return false;
}

std::string all(const std::vector<std::string>& report) {
    std::string s;
    for (const std::string& l : report)
        s += l + "\n";
    return s;
}

// The refusal message of importing a file ("" when it imports).
std::string refusal(const std::string& text) {
    try {
        (void)importDstv(text);
    } catch (const ImportError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Dstv, TheSectionSteelModuleRegistersTheDstvImporter) {
    JobImporter i;
    ASSERT_TRUE(findJobImporter("dstv", &i));
    EXPECT_EQ(i.patterns, (std::vector<std::string>{"*.nc", "*.nc1"}));
    ASSERT_TRUE(i.import);
    EXPECT_FALSE(findJobImporter("no-such-format", nullptr));
}

TEST(Dstv, HeaderOnlyGivesASquareEndOfTheCatalogueSection) {
    const std::string text = data("ipe300_square.nc1");
    const dstv::Part part = dstv::parseDstv(text);
    EXPECT_EQ(part.header.order, "ORDER-13");
    EXPECT_EQ(part.header.piece, "B1");
    EXPECT_EQ(part.header.quantity, 2);
    EXPECT_EQ(part.header.profile, "IPE300");
    EXPECT_EQ(part.header.length_mm, 5000);
    EXPECT_EQ(part.header.tf_mm, 10.7); // flange thickness before web thickness
    EXPECT_EQ(part.header.tw_mm, 7.1);
    EXPECT_EQ(part.header.text[0], "BEAM");
    EXPECT_EQ(part.header.text[1], "second text");
    EXPECT_EQ(part.end_line, 27);

    const ImportResult r = importDstv(text);
    const SectionSteelSpec& s = specOf(r.job);
    EXPECT_FALSE(s.user_defined);
    EXPECT_EQ(s.section.designation, "IPE 300");
    EXPECT_EQ(s.cut.mitre_horizontal_deg, 0);
    EXPECT_EQ(s.cut.mitre_vertical_deg, 0);
    EXPECT_EQ(s.cut.web.type, GrooveType::None);
    EXPECT_EQ(s.cut.flanges.type, GrooveType::None);
    EXPECT_TRUE(validateJob(r.job).empty());
    EXPECT_TRUE(hasLine(r.report, "line 8: ", "quantity 2")) << all(r.report);
    EXPECT_TRUE(hasLine(r.report, "line 19: ", "start end")) << all(r.report);
    EXPECT_EQ(r.report.size(), 2u) << all(r.report);
}

TEST(Dstv, SawCutAnglesAndAkWeldPreparationsBecomeMitresAndGrooves) {
    const ImportResult r = importDstv(data("ipe300_mitre_grooves.nc1"));
    const SectionSteelSpec& s = specOf(r.job);
    EXPECT_EQ(s.section.designation, "IPE 300");
    // The web end cut of 15 deg in DSTV's sense shortens the top of the web: the cell's mitre
    // about y lengthens it when positive (see dstv_import.cpp), so it is -15 here.
    EXPECT_EQ(s.cut.mitre_horizontal_deg, -15); // web end cut
    EXPECT_EQ(s.cut.mitre_vertical_deg, 0);     // flange end cut
    EXPECT_EQ(s.cut.web.type, GrooveType::V);
    EXPECT_EQ(s.cut.web.angle_deg, 30);
    EXPECT_EQ(s.cut.flanges.type, GrooveType::Y);
    EXPECT_EQ(s.cut.flanges.angle_deg, 30);
    EXPECT_EQ(s.cut.flanges.root_face_mm, 2);
    // The cope at the start end of the web is reported with its AK line, nothing else is.
    EXPECT_TRUE(hasLine(r.report, "line 23: ", "cope or notch at the start end on face v"))
        << all(r.report);
    EXPECT_FALSE(hasLine(r.report, "line ", "weld preparation")) << all(r.report);
    EXPECT_TRUE(validateJob(r.job).empty());
}

TEST(Dstv, HolesInnerContoursMarkingsAndOtherBlocksAreReportedLineByLine) {
    const std::string text = data("heb200_holes_marks.nc1");
    const dstv::Part part = dstv::parseDstv(text);
    ASSERT_EQ(part.holes.size(), 4u);
    EXPECT_EQ(part.holes[0].face, 'v');
    EXPECT_EQ(part.holes[0].x_ref, 'u');
    EXPECT_EQ(part.holes[0].diameter_mm, 22);
    EXPECT_TRUE(part.holes[2].slot);
    EXPECT_EQ(part.holes[2].slot_width_mm, 70);
    EXPECT_EQ(part.holes[3].kind, 's');
    EXPECT_EQ(part.holes[3].depth_mm, 8);
    ASSERT_EQ(part.contours.size(), 1u);
    EXPECT_FALSE(part.contours[0].outer);
    ASSERT_EQ(part.markings.size(), 1u);
    EXPECT_EQ(part.markings[0].text, "B3/1");
    EXPECT_EQ(part.markings[0].height_mm, 10);
    ASSERT_EQ(part.others.size(), 1u);
    EXPECT_EQ(part.others[0].code, "KO");

    const ImportResult r = importDstv(text);
    EXPECT_EQ(specOf(r.job).section.designation, "HEB 200");
    for (int line : {25, 26})
        EXPECT_TRUE(hasLine(r.report, "line " + std::to_string(line) + ": ",
                            "BO hole 22 mm on face v (front)"))
            << all(r.report);
    EXPECT_TRUE(hasLine(r.report, "line 27: ", "BO slot 18 mm, 70 x 0 mm")) << all(r.report);
    EXPECT_TRUE(hasLine(r.report, "line 28: ", "BO countersink 18 mm on face u")) << all(r.report);
    EXPECT_TRUE(hasLine(r.report, "line 29: ", "IK inner contour on face v")) << all(r.report);
    EXPECT_TRUE(hasLine(r.report, "line 36: ", "SI marking \"B3/1\"")) << all(r.report);
    EXPECT_TRUE(hasLine(r.report, "line 37: ", "KO block (punch marking, 2 lines)"))
        << all(r.report);
    // In file order.
    for (size_t i = 1; i < r.report.size(); ++i)
        EXPECT_LE(std::stoi(r.report[i - 1].substr(5)), std::stoi(r.report[i].substr(5)));
}

TEST(Dstv, AProfileOutsideTheCatalogueTakesTheHeaderDimensions) {
    const ImportResult r = importDstv(data("w21x44_user.nc1"));
    const SectionSteelSpec& s = specOf(r.job);
    EXPECT_TRUE(s.user_defined);
    EXPECT_EQ(s.section.family, SectionFamily::I);
    EXPECT_EQ(s.section.h_mm, 525.78);
    EXPECT_EQ(s.section.b_mm, 165.1);
    EXPECT_EQ(s.section.tf_mm, 11.43);
    EXPECT_EQ(s.section.tw_mm, 8.89);
    EXPECT_EQ(s.section.r_mm, 17.15);
    EXPECT_EQ(s.cut.mitre_horizontal_deg, 10); // the header's -10, in the cell's sense
    EXPECT_EQ(s.cut.mitre_vertical_deg, 5);
    EXPECT_TRUE(hasLine(r.report, "line 9: ", "not in the catalogue")) << all(r.report);
}

TEST(Dstv, AnAngleWithTwoEqualWeldPreparationsGetsAKGroove) {
    const ImportResult r = importDstv(data("l100_k_groove.nc1"));
    const SectionSteelSpec& s = specOf(r.job);
    EXPECT_EQ(s.section.designation, "L 100x100x10");
    EXPECT_EQ(s.cut.flanges.type, GrooveType::K); // horizontal leg (face u)
    EXPECT_EQ(s.cut.flanges.angle_deg, 30);
    EXPECT_EQ(s.cut.flanges.root_face_mm, 2);
    EXPECT_EQ(s.cut.web.type, GrooveType::None);
}

TEST(Dstv, BrokenFilesAreRefusedNamingTheLineAndTheField) {
    const struct {
        const char* file;
        const char* prefix;
        const char* part;
    } cases[] = {
        {"broken_unknown_block.nc1", "line 23: ", "unknown block \"XY\""},
        {"broken_truncated_header.nc1", "line 16: ", "field 14 (radius) missing"},
        {"broken_bad_number.nc1", "line 11: ",
         "length (header field 9) = \"5000,00\" is not a "
         "number (DSTV numbers take a decimal point)"},
        {"broken_bad_contour_number.nc1", "line 26: ", "y \"3OO.00\" is not a number"},
        {"broken_missing_en.nc1", "line 25: ", "without the EN block"},
        {"refused_plate.nc1", "line 10: ", "profile code B (a plate)"},
        {"refused_mitre_60.nc1", "line 20: ", "web end cut (header field 18) = 60 deg"},
    };
    for (const auto& c : cases) {
        const std::string why = refusal(data(c.file));
        EXPECT_EQ(why.rfind(c.prefix, 0), 0u) << c.file << ": " << why;
        EXPECT_NE(why.find(c.part), std::string::npos) << c.file << ": " << why;
    }
}

TEST(Dstv, SmallEditsAreRefusedWithTheirLine) {
    const std::string good = data("ipe300_mitre_grooves.nc1");
    const auto edit = [&](const std::string& from, const std::string& to) {
        std::string t = good;
        const size_t at = t.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return refusal(t.replace(at, from.size(), to));
    };
    // An open contour, a face change inside a contour, a bad face, a bad flag, out of range.
    EXPECT_EQ(edit("        0.00      0.00     0.00\n** the", "** the").rfind("line 29: ", 0), 0u);
    EXPECT_EQ(edit("     5000.00    150.00", "  o  5000.00    150.00").rfind("line 41: ", 0), 0u);
    EXPECT_EQ(edit("  u     0.00 ", "  x     0.00 ").rfind("line 39: face \"x\"", 0), 0u);
    EXPECT_EQ(edit("0.00u     0.00", "0.00q     0.00").rfind("line 24: x \"0.00q\"", 0), 0u);
    EXPECT_NE(edit("  15.000", "  95.000").find("line 20: web end cut (header field 18) = 95"),
              std::string::npos);
    EXPECT_EQ(edit("   30.00    0.00", "   30.00    -1.00")
                  .rfind("line 25: weld preparation "
                         "blunting 1 = -1",
                         0),
              0u);
    EXPECT_EQ(edit("ST\n", "ST\n  EXTRA\n").empty(), false); // one line too many: texts shift
    // A header line without its two blanks is read as writers in the wild make it (issue 22).
    EXPECT_EQ(edit("  IPE300\n", "IPE300\n"), "");
    EXPECT_EQ(edit("EN\n", "EN\n  1.00\n").rfind("line 45: text after the EN block", 0), 0u);
}

// Every prefix of a good file lacks its EN (or more): refused with a line number, never a
// crash or a silently partial job.
TEST(Dstv, EveryTruncationIsRefusedWithALineNumber) {
    for (const char* f : {"ipe300_mitre_grooves.nc1", "heb200_holes_marks.nc1"}) {
        const std::string text = data(f);
        size_t at = 0;
        int lines = 0;
        while ((at = text.find('\n', at)) != std::string::npos && at + 1 < text.size()) {
            ++at;
            ++lines;
            const std::string why = refusal(text.substr(0, at));
            ASSERT_EQ(why.rfind("line ", 0), 0u) << f << " cut after line " << lines << ": " << why;
            EXPECT_LE(std::stoi(why.substr(5)), lines + 1) << why;
        }
    }
}

TEST(Dstv, ImportedJobsRoundTripThroughTheJobFile) {
    for (const char* f : {"ipe300_square.nc1", "ipe300_mitre_grooves.nc1", "heb200_holes_marks.nc1",
                          "w21x44_user.nc1", "l100_k_groove.nc1"}) {
        const ImportResult r = importDstv(data(f));
        const std::string text = json::write(jobToJson(r.job));
        const Job back = parseJob(text);
        EXPECT_EQ(json::write(jobToJson(back)), text) << f;
    }
}

namespace {

// An NC1 text of an IPE 300 whose end (x = L) is cut at the given angles, the end edges of the
// web (v) and both flanges (o, u) carrying the given weld preparations ("" for none).
std::string mitredPiece(double webDeg, double flangeDeg, const std::string& webPrep,
                        const std::string& flangePrep) {
    const double L = 4000, h = 300, b = 150;
    const auto f = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.3f", v);
        return std::string(buf);
    };
    std::string t = "ST\n  O\n  D\n  1\n  P\n  S355\n  1\n  IPE300\n  I\n  " + f(L) +
                    "\n  300\n  150\n  10.7\n  7.1\n  15\n  42.2\n  1.16\n  0\n  " + f(webDeg) +
                    "\n  0\n  " + f(flangeDeg) + "\n";
    const auto face = [&](char c, double width, double deg, const std::string& prep) {
        const double top = L - width * std::tan(deg * 3.14159265358979323846 / 180);
        t += std::string("AK\n  ") + c + " 0 0 0\n  " + c + " " + f(L) + " 0 0 " + prep + "\n  " +
             c + " " + f(top) + " " + f(width) + " 0\n  " + c + " 0 " + f(width) + " 0\n  " + c +
             " 0 0 0\n";
    };
    face('v', h, webDeg, webPrep);
    face('o', b, flangeDeg, flangePrep);
    face('u', b, flangeDeg, flangePrep);
    return t + "EN\n";
}

} // namespace

// Written angles and preparations come back as the job's mitres and grooves, with no report
// line but the start end (which this job never cuts).
TEST(Dstv, MitresAndGroovesRoundTripThroughWrittenFiles) {
    const struct {
        const char* prep;
        GrooveType type;
    } preps[] = {{"", GrooveType::None},
                 {"25 0", GrooveType::V},
                 {"35 3", GrooveType::Y},
                 {"40 2 40 2", GrooveType::K}};
    int checked = 0;
    for (double web = -45; web <= 45; web += 7.5)
        for (double flange = -45; flange <= 45; flange += 15)
            for (const auto& wp : preps)
                for (const auto& fp : preps) {
                    const ImportResult r = importDstv(mitredPiece(web, flange, wp.prep, fp.prep));
                    const SectionSteelSpec& s = specOf(r.job);
                    ASSERT_NEAR(s.cut.mitre_horizontal_deg, -web, 1e-9); // the cell's sense
                    ASSERT_NEAR(s.cut.mitre_vertical_deg, flange, 1e-9);
                    ASSERT_EQ(s.cut.web.type, wp.type) << wp.prep;
                    ASSERT_EQ(s.cut.flanges.type, fp.type) << fp.prep;
                    if (fp.type == GrooveType::Y) {
                        EXPECT_EQ(s.cut.flanges.angle_deg, 35);
                        EXPECT_EQ(s.cut.flanges.root_face_mm, 3);
                    }
                    ASSERT_EQ(r.report.size(), 1u) << all(r.report);
                    EXPECT_NE(r.report[0].find("start end"), std::string::npos);
                    ++checked;
                }
    EXPECT_EQ(checked, 13 * 7 * 16);
}

// The reader never consults the locale: the same job under a decimal-comma C locale.
TEST(Dstv, NumbersReadTheSameUnderAGermanLocale) {
    const std::string text = data("w21x44_user.nc1");
    const std::string c = json::write(jobToJson(importDstv(text).job));
    const std::string saved = std::setlocale(LC_ALL, nullptr);
    if (!std::setlocale(LC_ALL, "de_DE.UTF-8")) GTEST_SKIP() << "locale de_DE.UTF-8 missing";
    std::string de;
    try {
        de = json::write(jobToJson(importDstv(text).job));
    } catch (...) {
    }
    std::setlocale(LC_ALL, saved.c_str());
    EXPECT_EQ(de, c);
}

namespace {

struct CliResult {
    int code;
    std::string out, err;
};

CliResult runCli(const std::string& args, const std::string& env) {
    const fs::path err =
        fs::temp_directory_path() / ("cutcell_dstv_err_" + std::to_string(::getpid()));
    const std::string cmd = env + " " + CUTCELL_CLI + " " + args + " 2>" + err.string();
    FILE* p = ::popen(cmd.c_str(), "r");
    CliResult r{-1, {}, {}};
    char buf[4096];
    while (p && std::fgets(buf, sizeof buf, p))
        r.out += buf;
    const int status = p ? ::pclose(p) : -1;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(err);
    r.err.assign(std::istreambuf_iterator<char>(in), {});
    fs::remove(err);
    return r;
}

} // namespace

TEST(Dstv, CliImportUnderAGermanLocaleWritesTheSameJobAndRefusesWithTheLine) {
    if (!std::setlocale(LC_ALL, "de_DE.UTF-8")) GTEST_SKIP() << "locale de_DE.UTF-8 missing";
    std::setlocale(LC_ALL, "C");
    const fs::path dir =
        fs::temp_directory_path() / ("cutcell_dstv_cli_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string in = dataPath("ipe300_mitre_grooves.nc1");
    const CliResult c =
        runCli("import-dstv " + in + " --out " + (dir / "c.json").string(), "LC_ALL=C");
    const CliResult de =
        runCli("import-dstv " + in + " --out " + (dir / "de.json").string(), "LC_ALL=de_DE.UTF-8");
    ASSERT_EQ(c.code, 0) << c.err;
    ASSERT_EQ(de.code, 0) << de.err;
    EXPECT_NE(de.out.find("line 23: AK cope or notch at the start end"), std::string::npos)
        << de.out;
    const std::string job = readTextFile((dir / "de.json").string());
    EXPECT_EQ(job, readTextFile((dir / "c.json").string()));
    EXPECT_NE(job.find("\"mitre_horizontal_deg\": -15"), std::string::npos);
    EXPECT_NE(job.find("\"root_face_mm\": 2"), std::string::npos);
    EXPECT_TRUE(validateJob(loadJobFile((dir / "de.json").string())).empty());

    const CliResult bad = runCli("import-dstv " + dataPath("broken_bad_number.nc1") + " --out " +
                                     (dir / "bad.json").string(),
                                 "LC_ALL=de_DE.UTF-8");
    EXPECT_EQ(bad.code, 2);
    EXPECT_NE(bad.err.find("line 11: length (header field 9)"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(dir / "bad.json"));
    const CliResult missing = runCli("import-dstv", "LC_ALL=C");
    EXPECT_EQ(missing.code, 64);
    fs::remove_all(dir);
}
