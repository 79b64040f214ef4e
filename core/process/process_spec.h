#pragma once
// The job's process section (issue 24): which cut-chart entry a torch machine cuts with, and the
// figures the operator set over the chart's. In a torch machine's section:
//
//   "process": { "process": "plasma", "material": "mild_steel", "consumable": "65A shielded",
//                "thickness_mm": 6,                     (optional: the wall of the part cut)
//                "override": { "kerf_mm": 1.7, "cut_speed_mm_min": 2200 },   (optional)
//                "lead_in": { "kind": "arc", "length_mm": 5 },                 (optional)
//                "lead_out": { "kind": "line", "length_mm": 3, "overlap_mm": 1 } }  (optional)
//
// The thickness picks the chart's row (interpolated between rows, refused outside the chart
// with its range: pickCutRow). An override replaces one figure of the row, is saved with the
// job and is reported as an override wherever the figure is shown. A job without the section
// cuts at its own cut.speed_mm_s without kerf compensation, as before the cut charts.
//
// The charts come from the active library: the shipped table unless the application installed
// the user's library at start-up (setActiveCutCharts, before any job is read).
#include "core/job/issue_checker.h"
#include "core/job/section_reader.h"
#include "core/process/cut_chart.h"
#include "core/process/process_spec_data.h"

#include <array>
#include <optional>
#include <string>

namespace cutcell {

// What a job cuts with: the chart's row, and the figures after the overrides.
struct ProcessSettings {
    Outcome outcome; // Refused: no such chart, or the thickness is outside it
    std::string chart_name;
    std::string chart_source;
    bool typical_values = true;
    double thickness_mm = 0;
    bool thickness_from_part = true; // the part's wall (no process.thickness_mm)
    CutRow chart_row;                // as the chart gives it at the thickness
    CutRow effective;                // chart_row with the overrides applied
    std::optional<int> life_pierces;
    std::optional<double> life_arc_minutes;
    std::optional<double> volts_per_mm;

    bool ok() const { return outcome.ok(); }
    bool overridden(CutFigure f) const { return effective.get(f) != chart_row.get(f); }
    // The kerf to compensate (0 when neither the chart nor an override gives one).
    double kerfMm() const { return effective.get(CutFigure::KerfMm).value_or(0.0); }
    double cutSpeedMmS() const { return effective.cutSpeedMmMin() / 60.0; }
};

const CutChartSet& activeCutCharts();
// Installs a library (the user's: cut_chart_library.h) for every later resolution; checked
// first (CutChartError). At start-up, and again when the editor saved the user's table: a
// reference from activeCutCharts() stays valid (a plan on another thread may hold one); the
// forms show the new table when they are next reloaded.
void setActiveCutCharts(CutChartSet set);

// Reads the optional "process" member of a machine section (unknown keys refused, overrides in
// their figures' ranges, a process the figure does not apply to refused).
void readProcess(SectionReader& section, ProcessSpec& spec);
void writeProcess(const ProcessSpec& spec, json::Object& section);
// The settings for a part with wall `partWall_mm` (used when the job gives no thickness).
ProcessSettings resolveProcess(const ProcessSpec& spec, double partWall_mm,
                               const CutChartSet& charts = activeCutCharts());
// The section's issues (keys process.*): an unknown chart entry, a thickness outside the chart,
// an override outside its range.
void checkProcess(IssueChecker& c, const ProcessSpec& spec, double partWall_mm);

// Lead-in / lead-out (process.lead_in, process.lead_out: { "kind": "line" | "arc" | "none",
// "length_mm": 5, "overlap_mm": 2 (lead-out only) }): a torch machine that pierces off the cut
// needs the pierce height and the cut height (chart or override). "" when the settings give
// both or no lead is asked for; else the key to set and one sentence naming it.
std::string leadHeightKey(const ProcessSpec& spec, const ProcessSettings& s);
std::string leadHeightProblem(const ProcessSpec& spec, const ProcessSettings& s);
// For a machine without a torch height control: process.torch_height is an issue.
void checkNoTorchHeight(IssueChecker& c, const ProcessSpec& spec, const char* machine);

} // namespace cutcell
