// DSTV files written by detailing software, not by CutCell (tests/data/dstv/public/, their
// origin in its README.md): every I, U or L section imports with its length and marks and
// plans - or, beyond the cell's reach, its plan is refused naming the joint and its limit -
// and every other piece (plates, tubes, special sections, a file without its EN) is refused
// naming the line and the reason. The batch command imports the whole folder with its table.
#include "core/job/job_io.h"
#include "core/machine/job_importer.h"
#include "core/machine/machine_registry.h"
#include "core/machines/section_steel/dstv/dstv_import.h"
#include "core/machines/section_steel/dstv/dstv_reader.h"
#include "core/machines/section_steel/section_steel_module.h"
#include "core/machines/section_steel/section_steel_spec.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <regex>
#include <set>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace cutcell;
using namespace cutcell::section_steel;

namespace {

const fs::path kPublic = fs::path(CUTCELL_SOURCE_DIR) / "tests/data/dstv/public";

std::vector<fs::path> publicFiles() {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(kPublic))
        if (e.path().extension() != ".md") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

const MachineModule& steel() {
    const MachineModule* m = findMachine(kSectionSteelId);
    if (!m) throw std::runtime_error("not registered");
    return *m;
}

} // namespace

TEST(DstvPublicFiles, EveryIULSectionImportsAndPlansEveryOtherPieceIsRefusedByLine) {
    const std::vector<fs::path> files = publicFiles();
    ASSERT_GE(files.size(), 15u) << "the set holds at least 15 files";
    int sections = 0, planned = 0, refused = 0;
    for (const fs::path& f : files) {
        SCOPED_TRACE(f.filename().string());
        const std::string text = readTextFile(f.string());
        const dstv::Header head = dstv::parseDstvHeader(text); // every header reads
        const bool iul =
            head.profile_code == "I" || head.profile_code == "U" || head.profile_code == "L";
        try {
            const ImportResult r = importDstv(text);
            ASSERT_TRUE(iul) << "a " << head.profile_code << " piece was imported";
            ++sections;
            const SectionSteelSpec& s = *r.job.machine_spec.as<SectionSteelSpec>();
            // The piece's own length and marks, as the header gives them.
            EXPECT_DOUBLE_EQ(s.length_mm, head.length_mm);
            EXPECT_EQ(s.piece.mark, head.piece);
            EXPECT_EQ(s.piece.order, head.order);
            EXPECT_EQ(s.piece.steel_grade, head.steel_grade);
            EXPECT_EQ(s.piece.quantity, head.quantity);
            // The job round-trips through its file.
            const Job again = parseJob(json::write(jobToJson(r.job)));
            EXPECT_EQ(again.machine_spec.as<SectionSteelSpec>()->piece.mark, head.piece);
            const MachinePlan plan = steel().plan(r.job, {});
            if (plan.ok()) {
                ++planned;
            } else {
                // Refused only for reach, with the joint and its limit.
                EXPECT_NE(plan.outcome.message.find("outside its limits"), std::string::npos)
                    << plan.outcome.message;
                EXPECT_GE(head.h_mm, 500)
                    << "a section of ordinary depth was not planned: " << plan.outcome.message;
            }
        } catch (const ImportError& e) {
            ++refused;
            const std::string why = e.what();
            EXPECT_TRUE(std::regex_search(why, std::regex("^line [0-9]+: "))) << why;
            if (!iul) {
                EXPECT_NE(why.find("profile code " + head.profile_code), std::string::npos) << why;
            }
        }
    }
    std::printf("public DSTV files: %zu, I/U/L sections imported %d (planned %d), refused %d\n",
                files.size(), sections, planned, refused);
    EXPECT_GE(sections, 10);
    EXPECT_GE(planned, sections - 1);
}

// The file of The Steel Detailer whose web end edge slopes 22.5 deg while its header says 0: the
// contour's angle is cut, with a warning naming the line; the example of a piece that
// was cut square.
TEST(DstvPublicFiles, AnEndContourThatDisagreesWithTheHeaderIsCutAsTheContourWithAWarning) {
    const ImportResult r =
        importDstv(readTextFile((kPublic / "tluijken-dstv_0008-SE0004.nc1").string()));
    const SectionSteelSpec& s = *r.job.machine_spec.as<SectionSteelSpec>();
    EXPECT_NEAR(s.cut.mitre_horizontal_deg, 22.5, 0.01);
    bool warned = false;
    for (const std::string& l : r.report)
        warned = warned || (l.rfind("line 28: warning: ", 0) == 0 &&
                            l.find("the contour's 22.5 deg is cut") != std::string::npos);
    EXPECT_TRUE(warned);
}

// The direction of a web mitre: both files draw the top of the web longer than its bottom
// (UPN: the header's -19.33 deg and the AK's top corner 56 mm further out; SE0004: a square
// header and the AK's top 82.84 mm further out), and the cell's cut plane x = (z - h/2) tan(m)
// puts the top further out (the kept bar at x < 0) for m > 0: both come out positive.
TEST(DstvPublicFiles, AWebMitreKeepsTheDirectionTheFileDraws) {
    const auto mitreOf = [](const char* file) {
        const ImportResult r = importDstv(readTextFile((kPublic / file).string()));
        return r.job.machine_spec.as<SectionSteelSpec>()->cut.mitre_horizontal_deg;
    };
    EXPECT_NEAR(mitreOf("dstvparser_UPN.nc"), 19.33, 1e-9);
    EXPECT_NEAR(mitreOf("tluijken-dstv_0008-SE0004.nc1"), 22.5, 0.01);
    // The file that draws the top shorter (header +26.01, AK top 112 mm back) comes out negative.
    EXPECT_NEAR(mitreOf("dstv-tools_1010_HEA240.nc_N_1_pz.nc"), -26.01, 1e-9);
}

// Tekla's "length,saw length" pair, headers without their leading blanks, lone CR line ends:
// read; a decimal comma is still refused as one.
TEST(DstvPublicFiles, TheFormsWrittenInTheWildAreRead) {
    const dstv::Header plate =
        dstv::parseDstvHeader(readTextFile((kPublic / "tluijken-dstv_P1565.nc").string()));
    EXPECT_DOUBLE_EQ(plate.length_mm, 233.7);
    EXPECT_DOUBLE_EQ(plate.saw_length_mm, 233.7);
    const std::string blanks = readTextFile((kPublic / "dstvparser_issue_1.nc1").string());
    EXPECT_EQ(dstv::parseDstvHeader(blanks).profile, "HI800-16-30*450");
    std::string cr = readTextFile((kPublic / "dstv-tools_2519.nc1").string());
    std::string lf = cr;
    for (char& c : cr)
        if (c == '\n') c = '\r';
    EXPECT_EQ(json::write(jobToJson(importDstv(cr).job)),
              json::write(jobToJson(importDstv(lf).job)));
}

// Edits of a real file as other writers make them: texts "  NA" and "EN 10025-2" (not blocks),
// a Latin-1 steel grade (read as such, said in the report), a 70-byte mark (cut on a character
// boundary; the job still loads), a decimal comma in the length (refused as one).
TEST(DstvPublicFiles, TextsCodePagesLongMarksAndDecimalCommas) {
    const std::string good = readTextFile((kPublic / "dstv-tools_2519.nc1").string());
    const auto edit = [&](const std::string& from, const std::string& to) {
        std::string t = good;
        const size_t at = t.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return t.replace(at, from.size(), to);
    };
    const std::string texts = edit("  0.000\n\n\n", "  0.000\n  NA\nEN 10025-2\n");
    EXPECT_EQ(dstv::parseDstvHeader(texts).text[0], "NA");
    EXPECT_EQ(dstv::parseDstvHeader(texts).text[1], "EN 10025-2");
    EXPECT_NO_THROW(importDstv(texts));
    const ImportResult latin = importDstv(edit("  S275JR\n", "  S275JR \xe4\xf6\n"));
    EXPECT_EQ(latin.job.machine_spec.as<SectionSteelSpec>()->piece.steel_grade,
              "S275JR \xc3\xa4\xc3\xb6");
    bool said = false;
    for (const std::string& l : latin.report)
        said = said || l.find("is not UTF-8: read as Latin-1") != std::string::npos;
    EXPECT_TRUE(said);
    const std::string longMark = std::string(63, 'A') + "\xc3\xa9" + "BCDE";
    const ImportResult cut =
        importDstv(edit("  2519\n  3\n  2519\n", "  2519\n  3\n  " + longMark + "\n"));
    const std::string mark = cut.job.machine_spec.as<SectionSteelSpec>()->piece.mark;
    EXPECT_EQ(mark, std::string(63, 'A')); // the 2-byte character does not fit: cut whole
    EXPECT_NO_THROW(parseJob(json::write(jobToJson(cut.job))));
    try {
        importDstv(edit("    1760.00\n", "    1000,500\n"));
        ADD_FAILURE() << "a decimal comma was read as a saw length";
    } catch (const ImportError& e) {
        EXPECT_NE(std::string(e.what()).find("DSTV numbers take a decimal point"),
                  std::string::npos)
            << e.what();
    }
}

TEST(DstvPublicFiles, TheBatchImportsTheFolderWithItsReportTable) {
    const fs::path out =
        fs::temp_directory_path() / ("cutcell_dstv_batch_" + std::to_string(getpid()));
    fs::remove_all(out);
    const std::string cmd = std::string(CUTCELL_CLI) + " import-dstv " + kPublic.string() +
                            " --out " + out.string() + " > " + (out.string() + ".txt") + " 2>&1";
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2) << "some files are refused: exit 2";
    const std::string csv = readTextFile((out / "import-report.csv").string());
    EXPECT_EQ(csv.rfind("file,result,job,piece,section,length_mm,quantity,steel,", 0), 0u) << csv;
    int rows = 0, imported = 0;
    for (size_t at = csv.find('\n'); at != std::string::npos && at + 1 < csv.size();
         at = csv.find('\n', at + 1)) {
        ++rows;
        if (csv.compare(csv.find(',', at) + 1, 9, "imported,") == 0) ++imported;
    }
    EXPECT_EQ(rows, static_cast<int>(publicFiles().size())) << "one row per file";
    int jobs = 0;
    for (const auto& e : fs::directory_iterator(out))
        if (e.path().extension() == ".json") {
            ++jobs;
            EXPECT_NO_THROW(loadJobFile(e.path().string())) << e.path();
        }
    EXPECT_EQ(jobs, imported);
    EXPECT_NE(
        csv.find("tluijken-dstv_P1.nc,imported,tluijken-dstv_P1.json,B_1,W21X44,6236.88,1,A992"),
        std::string::npos)
        << csv;
    fs::remove_all(out);
    fs::remove(out.string() + ".txt");
}
