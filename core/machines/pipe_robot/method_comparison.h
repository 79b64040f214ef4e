#pragma once
// Seed 000, Section 4 (Fig. 11-14): the same cut with the pipe static and with the pipe
// turning. Each method is planned (planCut) and simulated offline (simulateCut: the plant and
// the controllers of `cutcell-cli simulate`); a trace keeps, every sample_dt_s, the six joint
// errors (commanded - actual, deg, as TrackingStats and the PID count them) and the torch
// tip's error in the robot base frame (FK(actual) - FK(commanded), mm, as TrackingStats). The
// table's figures are taken over every control cycle, not only the kept samples.
//
// Threading contract: pure functions of their arguments; callable from any thread.
#include "core/common/types.h"
#include "core/job/job.h"
#include "core/json/json.h"
#include "core/machine/plan_options.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "core/sim/line_chart.h"
#include "core/sim/tracking_stats.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace cutcell {

struct CutTrace {
    CutMethod method = CutMethod::RotatingPipe;
    double sample_dt_s = 0; // between kept samples (a whole number of control periods)
    std::vector<double> t_s;
    std::array<std::vector<double>, kAxisCount> joint_error_deg; // commanded - actual
    std::array<std::vector<double>, 3> tip_error_mm;             // x, y, z: FK(act) - FK(cmd)
    // Over every cycle: max |joint error| (deg) and the tip error's range per axis (mm).
    std::array<double, kAxisCount> joint_max_abs_deg{};
    Vec3 tip_min_mm = Vec3::Zero(), tip_max_mm = Vec3::Zero();
    long cycles = 0;
    TrackingReport report; // simulateCut's own figures of the same run
};

// Simulates a planned (reachable) cut and keeps every n-th cycle, n = sampleDtS / period
// rounded (at least 1).
CutTrace traceCut(const Job& job, const CutPlan& plan, double sampleDtS = 0.01);

struct MethodRun {
    CutMethod method = CutMethod::RotatingPipe;
    bool ok = false;     // planned (reachable) and simulated
    std::string problem; // why not: the planner's sentence
    CutTrace trace;
};

struct MethodComparison {
    std::string job_name;
    double period_s = 0;
    std::array<MethodRun, 2> runs; // [0] static_pipe, [1] rotating_pipe
    bool cancelled = false;
    bool ok() const { return !cancelled && runs[0].ok && runs[1].ok; }
    const MethodRun& staticPipe() const { return runs[0]; }
    const MethodRun& rotatingPipe() const { return runs[1]; }
    // rotating / static of max |joint error| of an axis, and of max |tip error| of x, y or z;
    // NaN when either run failed or the static figure is ~0 (the static chuck does not move).
    double jointRatio(int axis) const;
    double tipRatio(int xyz) const;
};

// Both methods of the job (its own method is ignored). options.cancel stops between and inside
// the plans (cancelled set, runs not done are not ok).
MethodComparison runMethodComparison(const Job& job, const PlanOptions& options = {},
                                     double sampleDtS = 0.01);

// The axes' names as the comparison's table and charts write them ("0 chuck", "1", ... "5").
const std::array<std::string, kAxisCount>& comparisonAxisNames();
// comparison.json: the table (both methods, per joint and per tip axis, ratios; null where a
// ratio has no meaning) and the kept samples of both traces.
json::Value comparisonJson(const MethodComparison& c);
// comparison.md: the table in Markdown.
std::string comparisonMarkdown(const MethodComparison& c);
// The figures: file stem -> chart. joint_errors_static / _rotating (Fig. 11, 12),
// tip_errors_static / _rotating (Fig. 13, 14), max_joint_error (both methods per joint).
std::vector<std::pair<std::string, LineChart>> comparisonCharts(const MethodComparison& c);

} // namespace cutcell
