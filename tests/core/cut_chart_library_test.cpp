// The user's cut-chart table and its edits (core/process/cut_chart_library.h): the path under
// the data home, the user's table used instead of the shipped one when it exists, edits that
// set a figure, add and remove a row, refusals that name the chart, row, field, value, unit and
// limit as the reader's do, an atomic save that leaves no temporary file and reads back, and
// the active library replaced while a reference to the old one is still held.
#include "core/process/cut_chart_library.h"

#include "core/process/process_spec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include <unistd.h>

namespace cutcell {
namespace {

namespace fs = std::filesystem;

const std::string kDoc = R"({"format": "cutcell-cut-charts", "version": 1, "charts": [
  {"process": "plasma", "material": "mild_steel", "consumable": "45A", "source": "test",
   "typical_values": true,
   "columns": ["thickness_mm", "cut_speed_mm_min", "kerf_mm", "arc_voltage_v"],
   "rows": [[1, 8000, 1.2, 110], [3, 4000, 1.5, 120], [6, 1500, 1.9, 130]]},
  {"process": "oxy_fuel", "material": "mild_steel", "consumable": "tip 1", "source": "test",
   "typical_values": true, "columns": ["thickness_mm", "preheat_s", "cut_speed_mm_min"],
   "rows": [[6, 8, 740], [12, 14, 680]]}]})";

const char* const kChart = "cut chart 'plasma / mild_steel / 45A' (charts[0])";

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

fs::path tempDir(const std::string& name) {
    const fs::path d = fs::temp_directory_path() /
                       ("cutcell_chart_lib_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

template <class F> std::string refusal(F&& f) {
    try {
        f();
    } catch (const CutChartError& e) {
        return e.what();
    }
    return "";
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST(CutChartLibrary, TheUserTableLivesUnderTheDataHome) {
    EXPECT_EQ(userCutChartsPath("/data"), "/data/cutcell/cut_charts.json");
    const char* xdg = std::getenv("XDG_DATA_HOME");
    const std::string saved = xdg ? xdg : "";
    ::setenv("XDG_DATA_HOME", "/tmp/xdg_here", 1);
    EXPECT_EQ(defaultDataHome(), "/tmp/xdg_here");
    ::setenv("XDG_DATA_HOME", "", 1);
    const char* home = std::getenv("HOME");
    if (home && *home) {
        EXPECT_EQ(defaultDataHome(), std::string(home) + "/.local/share");
    }
    if (xdg)
        ::setenv("XDG_DATA_HOME", saved.c_str(), 1);
    else
        ::unsetenv("XDG_DATA_HOME");
}

TEST(CutChartLibrary, TheUserTableOverridesTheShippedOne) {
    const fs::path home = tempDir("override");
    CutChartsInUse shipped = loadCutChartsInUse(home.string());
    EXPECT_FALSE(shipped.user);
    EXPECT_EQ(shipped.set, shippedCutCharts());
    EXPECT_EQ(shipped.path, (home / "cutcell" / "cut_charts.json").string());

    const CutChartSet mine = parseCutCharts(kDoc);
    saveCutChartsFile(shipped.path, mine); // creates the folder
    CutChartsInUse user = loadCutChartsInUse(home.string());
    EXPECT_TRUE(user.user);
    EXPECT_EQ(user.set, mine);

    // An invalid user's table is an error naming the file, never silently the shipped one.
    std::ofstream(shipped.path) << "{\"format\": \"cutcell-cut-charts\"}";
    const std::string why = refusal([&] { loadCutChartsInUse(home.string()); });
    EXPECT_TRUE(has(why, shipped.path)) << why;
    fs::remove_all(home);
}

TEST(CutChartLibrary, SetAFigure) {
    const CutChartSet set = parseCutCharts(kDoc);
    const CutChartSet out =
        setCutChartFigure(set, CutProcess::Plasma, "mild_steel", "45A", 3, CutFigure::KerfMm, 1.55);
    EXPECT_EQ(out.charts[0].rows[1].get(CutFigure::KerfMm), 1.55);
    // Nothing else changed.
    CutChartSet back = out;
    back.charts[0].rows[1].set(CutFigure::KerfMm, 1.5);
    EXPECT_EQ(back, set);
    // By index, the thickness too (staying between its neighbours).
    const CutChartSet thicker = setCutChartFigure(set, 0, 1, CutFigure::ThicknessMm, 4);
    EXPECT_EQ(thicker.charts[0].rows[1].thicknessMm(), 4);
}

TEST(CutChartLibrary, RefusalsNameTheChartRowFieldValueUnitAndLimit) {
    const CutChartSet set = parseCutCharts(kDoc);
    std::string why = refusal([&] {
        setCutChartFigure(set, CutProcess::Plasma, "mild_steel", "45A", 3, CutFigure::KerfMm, 12);
    });
    EXPECT_EQ(why, std::string(kChart) + " rows[1]: kerf_mm = 12 mm is outside [0.05, 10] mm");
    why = refusal([&] { setCutChartFigure(set, 0, 0, CutFigure::CutSpeedMmMin, 0); });
    EXPECT_EQ(why, std::string(kChart) +
                       " rows[0]: cut_speed_mm_min = 0 mm/min is outside (0, 100000] mm/min");
    why = refusal([&] {
        setCutChartFigure(set, 0, 0, CutFigure::ArcVoltageV,
                          std::numeric_limits<double>::quiet_NaN());
    });
    EXPECT_TRUE(has(why, "rows[0]: arc_voltage_v = NaN V is outside [30, 400] V")) << why;
    // The thickness keeps the rows in increasing order.
    why = refusal([&] { setCutChartFigure(set, 0, 1, CutFigure::ThicknessMm, 7); });
    EXPECT_TRUE(has(why, "rows[2]: thickness_mm = 6 mm is not above rows[1]'s 7 mm")) << why;
    // A figure the chart does not give is not added to one row.
    why = refusal([&] { setCutChartFigure(set, 0, 0, CutFigure::PierceDelayS, 0.5); });
    EXPECT_TRUE(has(why, "pierce_delay_s is not a column of the chart")) << why;
    // No such chart or row: what exists is named.
    why = refusal([&] {
        setCutChartFigure(set, CutProcess::Plasma, "mild_steel", "30A", 3, CutFigure::KerfMm, 1);
    });
    EXPECT_TRUE(has(why, "no cut chart 'plasma / mild_steel / 30A'")) << why;
    EXPECT_TRUE(has(why, "45A")) << why;
    why = refusal([&] {
        setCutChartFigure(set, CutProcess::Plasma, "mild_steel", "45A", 2, CutFigure::KerfMm, 1);
    });
    EXPECT_TRUE(has(why, "no row at thickness_mm = 2 mm; its rows are at 1, 3, 6 mm")) << why;
    EXPECT_FALSE(refusal([&] { setCutChartFigure(set, 0, 9, CutFigure::KerfMm, 1); }).empty());
}

TEST(CutChartLibrary, AddARow) {
    const CutChartSet set = parseCutCharts(kDoc);
    CutRow row;
    row.set(CutFigure::ThicknessMm, 2);
    row.set(CutFigure::CutSpeedMmMin, 6000);
    row.set(CutFigure::KerfMm, 1.3);
    row.set(CutFigure::ArcVoltageV, 115);
    const CutChartSet out = addCutChartRow(set, CutProcess::Plasma, "mild_steel", "45A", row);
    ASSERT_EQ(out.charts[0].rows.size(), 4u);
    EXPECT_EQ(out.charts[0].rows[1], row); // in its place by thickness
    // After the last row and before the first.
    row.set(CutFigure::ThicknessMm, 8);
    EXPECT_EQ(addCutChartRow(set, 0, row).charts[0].rows.back(), row);
    row.set(CutFigure::ThicknessMm, 0.5);
    EXPECT_EQ(addCutChartRow(set, 0, row).charts[0].rows.front(), row);

    // Refusals: a thickness that has a row, a missing column, a figure of another process, a
    // value out of range (named at the row's new index).
    row.set(CutFigure::ThicknessMm, 3);
    std::string why = refusal([&] { addCutChartRow(set, 0, row); });
    EXPECT_TRUE(has(why, "thickness_mm = 3 mm has a row already (rows[1])")) << why;
    row.set(CutFigure::ThicknessMm, 2);
    CutRow missing = row;
    missing.figures[static_cast<std::size_t>(CutFigure::KerfMm)].reset();
    why = refusal([&] { addCutChartRow(set, 0, missing); });
    EXPECT_EQ(why,
              std::string(kChart) + " rows[1]: kerf_mm is missing (it is a column of the chart)");
    CutRow extra = row;
    extra.set(CutFigure::PreheatS, 3);
    why = refusal([&] { addCutChartRow(set, 0, extra); });
    EXPECT_TRUE(has(why, "rows[1]: preheat_s is given but is not a column of the chart")) << why;
    CutRow hot = row;
    hot.set(CutFigure::ArcVoltageV, 450);
    why = refusal([&] { addCutChartRow(set, 0, hot); });
    EXPECT_EQ(why, std::string(kChart) + " rows[1]: arc_voltage_v = 450 V is outside [30, 400] V");
    CutRow thick = row;
    thick.set(CutFigure::ThicknessMm, 301);
    why = refusal([&] { addCutChartRow(set, 0, thick); });
    EXPECT_TRUE(has(why, "rows[3]: thickness_mm = 301 mm is outside [0.1, 300] mm")) << why;
}

TEST(CutChartLibrary, RemoveARow) {
    const CutChartSet set = parseCutCharts(kDoc);
    const CutChartSet out = removeCutChartRow(set, CutProcess::Plasma, "mild_steel", "45A", 3);
    ASSERT_EQ(out.charts[0].rows.size(), 2u);
    EXPECT_EQ(out.charts[0].rows[1].thicknessMm(), 6);
    // The last row of a chart stays.
    CutChartSet one = removeCutChartRow(set, 1, 0);
    const std::string why = refusal([&] { removeCutChartRow(one, 1, 0); });
    EXPECT_EQ(why, "cut chart 'oxy_fuel / mild_steel / tip 1' (charts[1]): rows is empty (a chart "
                   "needs at least one row)");
    EXPECT_TRUE(
        has(refusal([&] { removeCutChartRow(set, CutProcess::Laser, "mild_steel", "x", 1); }),
            "the table has no charts for laser"));
}

TEST(CutChartLibrary, SaveIsAtomicReadsBackAndRoundTrips) {
    const fs::path dir = tempDir("save");
    const std::string path = (dir / "sub" / "cut_charts.json").string();
    CutChartSet set = parseCutCharts(kDoc);
    set = setCutChartFigure(set, 0, 1, CutFigure::CutSpeedMmMin, 4000.25);
    saveCutChartsFile(path, set);
    EXPECT_EQ(loadCutChartsFile(path), set);
    EXPECT_EQ(readText(path), writeCutCharts(set)); // the writer's text, byte for byte
    // Writing the file that was read gives its text back.
    EXPECT_EQ(writeCutCharts(loadCutChartsFile(path)), readText(path));
    // The shipped table as the user's first copy reads back as the shipped table.
    saveCutChartsFile(path, shippedCutCharts());
    EXPECT_EQ(readText(path), shippedCutChartsText());
    // No temporary file is left beside it.
    for (const auto& e : fs::directory_iterator(dir / "sub"))
        EXPECT_EQ(e.path().filename(), "cut_charts.json") << e.path();

    // An invalid table is refused and the file keeps its old text.
    const std::string before = readText(path);
    CutChartSet bad = set;
    bad.charts[0].rows[0].set(CutFigure::KerfMm, -1);
    const std::string why = refusal([&] { saveCutChartsFile(path, bad); });
    EXPECT_TRUE(has(why, "kerf_mm = -1 mm is outside [0.05, 10] mm")) << why;
    EXPECT_EQ(readText(path), before);
    // A folder where the file should be: an I/O error, not an invalid table.
    EXPECT_THROW(saveCutChartsFile(dir.string(), set), CutChartFileError);
    fs::remove_all(dir);
}

TEST(CutChartLibrary, TheActiveTableIsReplacedWhileAnOldReferenceIsHeld) {
    const CutChartSet& before = activeCutCharts();
    const std::size_t charts = before.charts.size();
    CutChartSet mine = parseCutCharts(kDoc);
    setActiveCutCharts(mine);
    EXPECT_EQ(activeCutCharts(), mine);
    setActiveCutCharts(shippedCutCharts());
    // The reference taken before both replacements still reads.
    EXPECT_EQ(before.charts.size(), charts);
    mine.charts[0].rows[0].set(CutFigure::KerfMm, 99); // refused: nothing replaced
    EXPECT_THROW(setActiveCutCharts(mine), CutChartError);
    EXPECT_EQ(activeCutCharts(), shippedCutCharts());
}

} // namespace
} // namespace cutcell
