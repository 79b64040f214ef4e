#pragma once
// The user's cut-chart table and its edits (issue 24). The shipped table (cut_chart.h,
// resources/process/cut_charts.json) stays read-only in the program; the user's table lives at
// <data home>/cutcell/cut_charts.json (data home: $XDG_DATA_HOME, else ~/.local/share) and,
// when it exists, is used instead of the shipped one. It starts as a copy of the shipped table
// at the first edit. The GUI's editor and `cutcell-cli materials` both edit through here.
//
// An edit is a pure function on the table: it returns the edited table or throws CutChartError
// with the first problem, found by the reader's own checks (checkCutCharts): the message names
// the chart, the row, the field, the value, the unit and the limit as the reader's do
// ("cut chart 'plasma / mild_steel / 45A' (charts[0]) rows[2]: kerf_mm = 12 mm is outside
// [0.05, 10] mm"). A table is saved atomically (a temporary file beside it, renamed over) and
// only after the text to be written has read back through the strict reader as the same table.
#include "core/process/cut_chart.h"

#include <cstddef>
#include <string>

namespace cutcell {

// $XDG_DATA_HOME when set and not empty, else $HOME/.local/share, else ".".
std::string defaultDataHome();
// <dataHome>/cutcell/cut_charts.json
std::string userCutChartsPath(const std::string& dataHome);

// The table the program uses: the user's when its file exists (read strictly: an invalid file
// is a CutChartError naming it, a file that cannot be read a CutChartFileError), else the
// shipped one.
struct CutChartsInUse {
    CutChartSet set;
    std::string path;  // the user's file (whether or not it exists)
    bool user = false; // the set is the user's file, not the shipped table
};
CutChartsInUse loadCutChartsInUse(const std::string& dataHome);

// Writes `set` to `path` atomically, creating the folder; the text is read back by the strict
// reader first and must give the same set (CutChartError otherwise, the file untouched). A
// file that cannot be written: CutChartFileError.
void saveCutChartsFile(const std::string& path, const CutChartSet& set);

// A chart by process, material and consumable; CutChartError naming what exists when there is
// none ("no cut chart 'plasma / mild_steel / 30A'; the consumable sets for plasma on
// mild_steel are ...").
std::size_t findCutChart(const CutChartSet& set, CutProcess p, const std::string& material,
                         const std::string& consumable);
// The row of a chart at exactly this thickness; CutChartError listing the chart's thicknesses.
std::size_t findCutRow(const CutChartSet& set, std::size_t chart, double thickness_mm);

// Sets one figure of one row (the thickness too: the rows must stay in increasing thickness).
// A figure that is not a column of the chart is refused (the library never adds a figure the
// chart's source does not give to a single row).
CutChartSet setCutChartFigure(const CutChartSet& set, std::size_t chart, std::size_t row,
                              CutFigure figure, double value);
CutChartSet setCutChartFigure(const CutChartSet& set, CutProcess p, const std::string& material,
                              const std::string& consumable, double thickness_mm, CutFigure figure,
                              double value);
// Adds a row (its thickness and every column of the chart, nothing else), in its place by
// thickness; a thickness the chart has already is refused.
CutChartSet addCutChartRow(const CutChartSet& set, std::size_t chart, const CutRow& row);
CutChartSet addCutChartRow(const CutChartSet& set, CutProcess p, const std::string& material,
                           const std::string& consumable, const CutRow& row);
// Removes a row; the last row of a chart is refused (a chart needs at least one row).
CutChartSet removeCutChartRow(const CutChartSet& set, std::size_t chart, std::size_t row);
CutChartSet removeCutChartRow(const CutChartSet& set, CutProcess p, const std::string& material,
                              const std::string& consumable, double thickness_mm);

} // namespace cutcell
