// The user's cut-chart table and its edits (cut_chart_library.h). Every limit is the reader's:
// an edit changes a copy and runs checkCutCharts over it.
#include "core/process/cut_chart_library.h"

#include "core/common/c_format.h"
#include "core/job/job_io.h"
#include "core/json/json.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace cutcell {
namespace {

namespace fs = std::filesystem;

std::string num(double v) {
    return formatC("%.6g", v);
}

std::string join(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names)
        out += (out.empty() ? "" : ", ") + n;
    return out;
}

// As the reader names a chart: "cut chart 'plasma / mild_steel / 45A' (charts[2])".
std::string chartLabel(const CutChartSet& set, std::size_t i) {
    return "cut chart '" + set.charts[i].name() + "' (charts[" + std::to_string(i) + "])";
}

std::string thicknesses(const CutChart& c) {
    std::string out;
    for (const CutRow& r : c.rows)
        out += (out.empty() ? "" : ", ") + num(r.thicknessMm());
    return out + " mm";
}

void checkChartIndex(const CutChartSet& set, std::size_t chart) {
    if (chart >= set.charts.size())
        throw CutChartError("cut charts: there is no charts[" + std::to_string(chart) +
                            "] (the table has " + std::to_string(set.charts.size()) + " charts)");
}

void checkRowIndex(const CutChartSet& set, std::size_t chart, std::size_t row) {
    checkChartIndex(set, chart);
    const std::size_t n = set.charts[chart].rows.size();
    if (row >= n)
        throw CutChartError(chartLabel(set, chart) + ": there is no rows[" + std::to_string(row) +
                            "] (the chart has " + std::to_string(n) + " rows)");
}

// The reader's checks over the edited table: the first problem is the edit's (the table was
// valid before it).
CutChartSet checked(CutChartSet set) {
    checkCutCharts(set);
    return set;
}

} // namespace

std::string defaultDataHome() {
    if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg) return xdg;
    if (const char* home = std::getenv("HOME"); home && *home)
        return (fs::path(home) / ".local" / "share").string();
    return ".";
}

std::string userCutChartsPath(const std::string& dataHome) {
    return (fs::path(dataHome) / "cutcell" / "cut_charts.json").string();
}

CutChartsInUse loadCutChartsInUse(const std::string& dataHome) {
    CutChartsInUse out;
    out.path = userCutChartsPath(dataHome);
    std::error_code ec;
    if (fs::exists(out.path, ec)) {
        out.set = loadCutChartsFile(out.path);
        out.user = true;
    } else {
        out.set = shippedCutCharts();
    }
    return out;
}

void saveCutChartsFile(const std::string& path, const CutChartSet& set) {
    const std::string text = writeCutCharts(set); // checks the set
    // The strict reader over the very text to be written: a written table always reads back.
    CutChartSet back;
    try {
        back = parseCutCharts(text);
    } catch (const CutChartError& e) {
        throw CutChartError(path + ": the table to be written does not read back (" + e.what() +
                            "); nothing was written");
    }
    if (back != set)
        throw CutChartError(path + ": the table to be written reads back as another table; "
                                   "nothing was written");
    const fs::path target(path);
    if (target.has_parent_path()) {
        std::error_code ec;
        fs::create_directories(target.parent_path(), ec);
        if (ec)
            throw CutChartFileError("cut charts: cannot create the folder " +
                                    target.parent_path().string() + ": " + ec.message());
    }
    try {
        writeFileAtomically(path, text);
    } catch (const JobError& e) {
        throw CutChartFileError(std::string("cut charts: ") + e.what());
    }
}

std::size_t findCutChart(const CutChartSet& set, CutProcess p, const std::string& material,
                         const std::string& consumable) {
    for (std::size_t i = 0; i < set.charts.size(); ++i) {
        const CutChart& c = set.charts[i];
        if (c.process == p && c.material == material && c.consumable == consumable) return i;
    }
    const std::string name = std::string(toString(p)) + " / " + material + " / " + consumable;
    const std::vector<std::string> materials = set.materials(p);
    if (materials.empty())
        throw CutChartError("no cut chart '" + name + "': the table has no charts for " +
                            toString(p));
    if (std::find(materials.begin(), materials.end(), material) == materials.end())
        throw CutChartError("no cut chart '" + name + "'; the materials for " + toString(p) +
                            " are " + join(materials));
    throw CutChartError("no cut chart '" + name + "'; the consumable sets for " + toString(p) +
                        " on " + material + " are " + join(set.consumables(p, material)));
}

std::size_t findCutRow(const CutChartSet& set, std::size_t chart, double thickness_mm) {
    checkChartIndex(set, chart);
    const CutChart& c = set.charts[chart];
    for (std::size_t r = 0; r < c.rows.size(); ++r)
        if (c.rows[r].thicknessMm() == thickness_mm) return r;
    throw CutChartError(chartLabel(set, chart) + ": no row at thickness_mm = " + num(thickness_mm) +
                        " mm; its rows are at " + thicknesses(c));
}

CutChartSet setCutChartFigure(const CutChartSet& set, std::size_t chart, std::size_t row,
                              CutFigure figure, double value) {
    checkRowIndex(set, chart, row);
    const CutChart& c = set.charts[chart];
    if (std::find(c.columns.begin(), c.columns.end(), figure) == c.columns.end()) {
        std::vector<std::string> cols;
        for (const CutFigure f : c.columns)
            cols.emplace_back(cutFigureInfo(f).key);
        throw CutChartError(chartLabel(set, chart) + " rows[" + std::to_string(row) +
                            "]: " + cutFigureInfo(figure).key +
                            " is not a column of the chart (its columns are " + join(cols) +
                            "); a figure the chart's source does not give is not added");
    }
    CutChartSet out = set;
    out.charts[chart].rows[row].set(figure, value);
    return checked(std::move(out));
}

CutChartSet setCutChartFigure(const CutChartSet& set, CutProcess p, const std::string& material,
                              const std::string& consumable, double thickness_mm, CutFigure figure,
                              double value) {
    const std::size_t chart = findCutChart(set, p, material, consumable);
    return setCutChartFigure(set, chart, findCutRow(set, chart, thickness_mm), figure, value);
}

CutChartSet addCutChartRow(const CutChartSet& set, std::size_t chart, const CutRow& row) {
    checkChartIndex(set, chart);
    const CutChart& c = set.charts[chart];
    const double t = row.thicknessMm();
    const auto at = std::find_if(c.rows.begin(), c.rows.end(),
                                 [t](const CutRow& r) { return !(r.thicknessMm() < t); });
    if (at != c.rows.end() && at->thicknessMm() == t)
        throw CutChartError(chartLabel(set, chart) + ": thickness_mm = " + num(t) +
                            " mm has a row already (rows[" + std::to_string(at - c.rows.begin()) +
                            "]); set its figures instead");
    CutChartSet out = set;
    auto& rows = out.charts[chart].rows;
    rows.insert(rows.begin() + (at - c.rows.begin()), row);
    return checked(std::move(out)); // a missing or extra figure, a value out of its range
}

CutChartSet addCutChartRow(const CutChartSet& set, CutProcess p, const std::string& material,
                           const std::string& consumable, const CutRow& row) {
    return addCutChartRow(set, findCutChart(set, p, material, consumable), row);
}

CutChartSet removeCutChartRow(const CutChartSet& set, std::size_t chart, std::size_t row) {
    checkRowIndex(set, chart, row);
    CutChartSet out = set;
    auto& rows = out.charts[chart].rows;
    rows.erase(rows.begin() + static_cast<std::ptrdiff_t>(row));
    return checked(std::move(out)); // the last row: "rows is empty (a chart needs ...)"
}

CutChartSet removeCutChartRow(const CutChartSet& set, CutProcess p, const std::string& material,
                              const std::string& consumable, double thickness_mm) {
    const std::size_t chart = findCutChart(set, p, material, consumable);
    return removeCutChartRow(set, chart, findCutRow(set, chart, thickness_mm));
}

} // namespace cutcell
