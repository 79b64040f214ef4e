#pragma once
// The cut-chart library (issue 24): per process (plasma, oxy-fuel, laser), material and
// consumable set, a table of rows by plate thickness with the figures a cut needs - kerf, cut
// speed, pierce height and delay, cut height, arc voltage (plasma), preheat (oxy-fuel) - and per
// consumable set its expected life and, for plasma, the arc-voltage slope over standoff. The
// shipped table is resources/process/cut_charts.json (its README says where each figure comes
// from). A figure a chart's source does not give is absent (not a column), never guessed.
//
// The file (format "cutcell-cut-charts", version 1) is read strictly: unknown keys, a value out
// of its physical range, thicknesses not strictly increasing and a second chart with the same
// process, material and consumable are refused with a message that names the chart, the field,
// the value, the unit and the limit (CutChartError). pick() interpolates every figure linearly
// in thickness between the two neighbouring rows (exact at a row) and refuses a thickness
// outside the chart, stating the chart's range. Units: mm, mm/min, s, V, V/mm, minutes.
#include "core/common/outcome.h"
#include "core/json/json.h"

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace cutcell {

enum class CutProcess : std::uint8_t { Plasma, OxyFuel, Laser };
// "plasma", "oxy_fuel", "laser".
const char* toString(CutProcess p);
std::optional<CutProcess> cutProcessFromString(std::string_view s);

// The figures of a row; each is a column of a chart. Thickness and cut speed are in every chart.
enum class CutFigure : std::uint8_t {
    ThicknessMm,
    KerfMm,
    CutSpeedMmMin,
    PierceHeightMm,
    PierceDelayS,
    CutHeightMm,
    ArcVoltageV, // plasma only
    PreheatS,    // oxy-fuel only
};
inline constexpr std::size_t kCutFigureCount = 8;

// A figure's key in the file, its unit and its physical range [lo, hi] (lo excluded when
// loOpen: a cut speed is > 0).
struct CutFigureInfo {
    const char* key; // "kerf_mm"
    const char* unit;
    double lo, hi;
    bool loOpen;
};
const CutFigureInfo& cutFigureInfo(CutFigure f);
std::optional<CutFigure> cutFigureFromKey(std::string_view key);
// Whether a chart of this process may give the figure (arc voltage: plasma; preheat: oxy-fuel).
bool cutFigureApplies(CutFigure f, CutProcess p);

// One row, or the result of pick(): the figures the chart gives, the others absent.
struct CutRow {
    std::array<std::optional<double>, kCutFigureCount> figures{};

    std::optional<double> get(CutFigure f) const { return figures[static_cast<std::size_t>(f)]; }
    void set(CutFigure f, double v) { figures[static_cast<std::size_t>(f)] = v; }
    double thicknessMm() const { return get(CutFigure::ThicknessMm).value_or(0.0); }
    double cutSpeedMmMin() const { return get(CutFigure::CutSpeedMmMin).value_or(0.0); }
    bool operator==(const CutRow&) const = default;
};

struct CutChart {
    CutProcess process = CutProcess::Plasma;
    std::string material;       // "mild_steel": lower case, digits and '_'
    std::string consumable;     // the consumable set: "45A shielded", "tip 1"
    std::string source;         // where the figures come from (required, not empty)
    bool typical_values = true; // the figures are a manufacturer's typical values, not measured
    // Per consumable set; absent when the source does not give it.
    std::optional<int> life_pierces;        // pierces
    std::optional<double> life_arc_minutes; // arc-on (flame-on) minutes
    std::optional<double> volts_per_mm;     // plasma: arc voltage change per mm of standoff
    // The figures this chart gives, in the file's column order (thickness and cut speed always).
    std::vector<CutFigure> columns;
    std::vector<CutRow> rows; // strictly increasing thickness

    // "plasma / mild_steel / 45A shielded"
    std::string name() const;
    bool operator==(const CutChart&) const = default;
};

struct CutChartSet {
    int version = 1;
    std::string note; // free text of the file (optional)
    std::vector<CutChart> charts;

    const CutChart* find(CutProcess p, const std::string& material,
                         const std::string& consumable) const;
    // In file order, without repeats.
    std::vector<std::string> materials(CutProcess p) const;
    std::vector<std::string> consumables(CutProcess p, const std::string& material) const;
    bool operator==(const CutChartSet&) const = default;
};

inline constexpr const char* kCutChartFormat = "cutcell-cut-charts";
inline constexpr int kCutChartVersion = 1;

// The table cannot be read or is not valid; the message names the chart, the field, the value,
// the unit and the limit (or the JSON line and column).
struct CutChartError : std::runtime_error {
    explicit CutChartError(const std::string& msg) : std::runtime_error(msg) {}
};
// The file cannot be read at all (missing, a folder, no permission): an I/O error, not an
// invalid table (the CLI's exit 1, not 2).
struct CutChartFileError : CutChartError {
    using CutChartError::CutChartError;
};

CutChartSet parseCutCharts(const std::string& text);
CutChartSet readCutCharts(const json::Value& doc);
// Reads the file; CutChartError naming the path when it cannot be read or is not valid.
CutChartSet loadCutChartsFile(const std::string& path);
// Throws CutChartError for the first problem of a set built in code (the GUI's editor): the
// same checks as parsing, plus NaN / Inf and rows that do not match the chart's columns.
void checkCutCharts(const CutChartSet& set);
// The document and its text (2-space indent, a row per line); checks the set first. Parsing the
// text gives the same set back, and writing a parsed file gives its text back.
json::Value cutChartsJson(const CutChartSet& set);
std::string writeCutCharts(const CutChartSet& set);

// The starter table shipped with CutCell (resources/process/cut_charts.json, compiled in), as
// text and parsed once.
const std::string& shippedCutChartsText();
const CutChartSet& shippedCutCharts();

// The row for a plate (wall) thickness: Ok with every figure of the chart interpolated linearly
// between the two neighbouring rows (exact at a row); Refused with the reason - no chart for the
// process, an unknown material or consumable (with the known ones), or a thickness outside the
// chart ("12.7 mm is outside the chart 'plasma / mild_steel / 45A shielded': 0.5 .. 10 mm").
// The outcome's key is the job key it is about: process.material, process.consumable or
// process.thickness_mm.
struct CutPick {
    Outcome outcome;
    CutRow row;                      // when ok
    const CutChart* chart = nullptr; // the chart picked (also when the thickness is refused)
    bool ok() const { return outcome.ok(); }
};
CutPick pickCutRow(const CutChartSet& set, CutProcess p, const std::string& material,
                   const std::string& consumable, double thickness_mm);
// The same within one chart.
CutPick pickCutRow(const CutChart& chart, double thickness_mm);

} // namespace cutcell
