#include "core/machines/pipe_robot/method_comparison.h"

#include "core/common/c_format.h"
#include "core/machines/pipe_robot/cut_simulation.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"
#include "core/machines/pipe_robot/pipe_robot_program.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace cutcell {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Below this a static figure is "no error" (the chuck holds still): no ratio.
constexpr double kTiny = 1e-12;
const char* const kXyz[3] = {"x", "y", "z"};

double ratio(double rotating, double fixed) {
    if (!std::isfinite(rotating) || !std::isfinite(fixed) || std::fabs(fixed) < kTiny) return kNaN;
    return rotating / fixed;
}

double tipMaxAbs(const CutTrace& t, int k) {
    return std::max(std::fabs(t.tip_min_mm[k]), std::fabs(t.tip_max_mm[k]));
}

json::Value numberOrNull(double v) {
    return std::isfinite(v) ? json::Value(v) : json::Value(nullptr);
}

std::string methodTitle(CutMethod m) {
    return m == CutMethod::StaticPipe ? "static pipe" : "rotating pipe";
}

} // namespace

CutTrace traceCut(const Job& job, const CutPlan& plan, double sampleDtS) {
    CutTrace trace;
    trace.method = plan.method;
    const double period = job.sim.period_s;
    const long every = std::max(1L, std::lround(sampleDtS / period));
    trace.sample_dt_s = static_cast<double>(every) * period;
    const PipeRobotTipModel tipModel(pipeRobotSpec(job).dh);
    const double simulated = std::max(job.sim.duration_s, plan.cut_time_s);
    const size_t kept = static_cast<size_t>(simulated / trace.sample_dt_s) + 2;
    trace.t_s.reserve(kept);
    for (auto& v : trace.joint_error_deg)
        v.reserve(kept);
    for (auto& v : trace.tip_error_mm)
        v.reserve(kept);
    bool first = true;
    const auto onSample = [&](double t, const JointVector& ref, const JointVector& actual) {
        const TipSample tips = tipSample(&tipModel, ref, actual);
        const Vec3 tipError = tips.error();
        const long k = trace.cycles++;
        for (int i = 0; i < kAxisCount; ++i)
            trace.joint_max_abs_deg[static_cast<size_t>(i)] =
                std::max(trace.joint_max_abs_deg[static_cast<size_t>(i)],
                         std::fabs(rad2deg(ref[i] - actual[i])));
        trace.tip_min_mm = first ? tipError : trace.tip_min_mm.cwiseMin(tipError);
        trace.tip_max_mm = first ? tipError : trace.tip_max_mm.cwiseMax(tipError);
        first = false;
        if (k % every != 0) return;
        trace.t_s.push_back(t);
        for (int i = 0; i < kAxisCount; ++i)
            trace.joint_error_deg[static_cast<size_t>(i)].push_back(rad2deg(ref[i] - actual[i]));
        for (int a = 0; a < 3; ++a)
            trace.tip_error_mm[static_cast<size_t>(a)].push_back(tipError[a]);
    };
    trace.report = simulateCut(job, plan, onSample);
    // TrackingStats starts its range at 0 (an untouched report says 0, 0): the same here.
    trace.tip_min_mm = trace.tip_min_mm.cwiseMin(Vec3::Zero());
    trace.tip_max_mm = trace.tip_max_mm.cwiseMax(Vec3::Zero());
    return trace;
}

double MethodComparison::jointRatio(int axis) const {
    if (!ok()) return kNaN;
    const auto a = static_cast<size_t>(axis);
    return ratio(runs[1].trace.joint_max_abs_deg[a], runs[0].trace.joint_max_abs_deg[a]);
}

double MethodComparison::tipRatio(int xyz) const {
    if (!ok()) return kNaN;
    return ratio(tipMaxAbs(runs[1].trace, xyz), tipMaxAbs(runs[0].trace, xyz));
}

MethodComparison runMethodComparison(const Job& job, const PlanOptions& options, double sampleDtS) {
    MethodComparison c;
    c.job_name = job.name;
    c.period_s = job.sim.period_s;
    const CutMethod methods[2] = {CutMethod::StaticPipe, CutMethod::RotatingPipe};
    for (size_t m = 0; m < 2; ++m) {
        MethodRun& run = c.runs[m];
        run.method = methods[m];
        if (options.cancelled()) {
            c.cancelled = true;
            continue;
        }
        Job j = job;
        pipeRobotSpec(j).method = methods[m];
        // Each plan reports half of the progress.
        PlanOptions planOptions;
        planOptions.cancel = options.cancel;
        if (options.progress)
            planOptions.progress = [&options, m](double f) {
                options.progress((static_cast<double>(m) + 0.5 * f) / 2);
            };
        const CutPlan plan = planCut(j, planOptions);
        if (plan.cancelled || options.cancelled()) {
            c.cancelled = true;
            continue;
        }
        if (!plan.reachable) {
            run.problem = plan.problem.empty() ? "path not reachable" : plan.problem;
            continue;
        }
        run.trace = traceCut(j, plan, sampleDtS);
        run.ok = true;
        if (options.progress) options.progress(static_cast<double>(m + 1) / 2);
    }
    return c;
}

const std::array<std::string, kAxisCount>& comparisonAxisNames() {
    static const std::array<std::string, kAxisCount> names = {"0 chuck", "1", "2", "3", "4", "5"};
    return names;
}

json::Value comparisonJson(const MethodComparison& c) {
    json::Array joints;
    for (int i = 0; i < kAxisCount; ++i) {
        const auto a = static_cast<size_t>(i);
        json::Object row{{"axis", i}, {"name", comparisonAxisNames()[a]}};
        for (const MethodRun& r : c.runs)
            row.emplace_back(std::string(toString(r.method)) + "_max_abs_deg",
                             r.ok ? json::Value(r.trace.joint_max_abs_deg[a]) : json::Value());
        row.emplace_back("rotating_over_static", numberOrNull(c.jointRatio(i)));
        joints.push_back(std::move(row));
    }
    json::Array tip;
    for (int k = 0; k < 3; ++k) {
        json::Object row{{"axis", kXyz[k]}};
        for (const MethodRun& r : c.runs) {
            const std::string m = toString(r.method);
            row.emplace_back(m + "_min_mm", r.ok ? json::Value(r.trace.tip_min_mm[k]) : nullptr);
            row.emplace_back(m + "_max_mm", r.ok ? json::Value(r.trace.tip_max_mm[k]) : nullptr);
        }
        row.emplace_back("rotating_over_static", numberOrNull(c.tipRatio(k)));
        tip.push_back(std::move(row));
    }
    json::Object methods;
    for (const MethodRun& r : c.runs) {
        json::Object m{{"ok", r.ok}};
        if (!r.ok) {
            m.emplace_back("problem", r.problem);
        } else {
            const CutTrace& t = r.trace;
            m.emplace_back("cycles", static_cast<std::int64_t>(t.cycles));
            m.emplace_back("sample_dt_s", t.sample_dt_s);
            m.emplace_back("cut_time_s", t.report.cut_time_s);
            m.emplace_back("simulated_s", t.report.simulated_s);
            json::Object series{{"t_s", json::Array(t.t_s.begin(), t.t_s.end())}};
            json::Array je;
            for (const auto& v : t.joint_error_deg)
                je.push_back(json::Array(v.begin(), v.end()));
            series.emplace_back("joint_error_deg", std::move(je));
            for (int k = 0; k < 3; ++k) {
                const auto& v = t.tip_error_mm[static_cast<size_t>(k)];
                series.emplace_back(std::string("tip_error_") + kXyz[k] + "_mm",
                                    json::Array(v.begin(), v.end()));
            }
            m.emplace_back("series", std::move(series));
        }
        methods.emplace_back(toString(r.method), std::move(m));
    }
    return json::Object{
        {"job", c.job_name},
        {"period_s", c.period_s},
        {"definitions", json::Object{{"joint_error", "commanded - actual (deg), every cycle"},
                                     {"tip_error", "FK(actual) - FK(commanded) in the robot "
                                                   "base frame (mm), every cycle"},
                                     {"series", "every sample_dt_s"}}},
        {"table", json::Object{{"joints", std::move(joints)}, {"tip", std::move(tip)}}},
        {"methods", std::move(methods)}};
}

std::string comparisonMarkdown(const MethodComparison& c) {
    const auto cell = [](bool ok, double v, const char* fmt) {
        // A value that rounds to zero is written "0", never "-0.000000".
        return ok && std::isfinite(v) ? formatC(fmt, std::fabs(v) < 5e-7 ? 0.0 : v)
                                      : std::string("n/a");
    };
    const MethodRun& s = c.staticPipe();
    const MethodRun& r = c.rotatingPipe();
    std::string md = formatC("# Cutting methods compared: %s\n\n", c.job_name.c_str());
    md += formatC("Offline simulation at %.4g s per cycle (seed 000, Section 4, Fig. 11-14).\n"
                  "Joint error: commanded - actual; tip error: FK(actual) - FK(commanded) in the "
                  "robot base frame. Figures over every cycle.\n\n",
                  c.period_s);
    for (const MethodRun& m : c.runs)
        if (!m.ok)
            md += formatC("**%s: not simulated** - %s\n\n", methodTitle(m.method).c_str(),
                          c.cancelled && m.problem.empty() ? "cancelled" : m.problem.c_str());
    md += "## Max |joint error| (deg)\n\n"
          "| joint | static pipe | rotating pipe | rotating / static |\n"
          "|---|---:|---:|---:|\n";
    for (int i = 0; i < kAxisCount; ++i) {
        const auto a = static_cast<size_t>(i);
        md += formatC("| %s | %s | %s | %s |\n", comparisonAxisNames()[a].c_str(),
                      cell(s.ok, s.trace.joint_max_abs_deg[a], "%.6f").c_str(),
                      cell(r.ok, r.trace.joint_max_abs_deg[a], "%.6f").c_str(),
                      cell(true, c.jointRatio(i), "%.3f").c_str());
    }
    md += "\n## Tip error, base frame (mm)\n\n"
          "| axis | static min | static max | rotating min | rotating max | "
          "rotating / static (max abs) |\n"
          "|---|---:|---:|---:|---:|---:|\n";
    for (int k = 0; k < 3; ++k)
        md += formatC("| %s | %s | %s | %s | %s | %s |\n", kXyz[k],
                      cell(s.ok, s.trace.tip_min_mm[k], "%.6f").c_str(),
                      cell(s.ok, s.trace.tip_max_mm[k], "%.6f").c_str(),
                      cell(r.ok, r.trace.tip_min_mm[k], "%.6f").c_str(),
                      cell(r.ok, r.trace.tip_max_mm[k], "%.6f").c_str(),
                      cell(true, c.tipRatio(k), "%.3f").c_str());
    return md;
}

std::vector<std::pair<std::string, LineChart>> comparisonCharts(const MethodComparison& c) {
    std::vector<std::pair<std::string, LineChart>> out;
    for (const MethodRun& r : c.runs) {
        const std::string suffix = r.method == CutMethod::StaticPipe ? "static" : "rotating";
        const std::string title = methodTitle(r.method);
        LineChart joints{"Joint errors, " + title, "t (s)", "commanded - actual (deg)", {}, {}};
        LineChart tip{
            "Tip position error, " + title, "t (s)", "FK(actual) - FK(commanded) (mm)", {}, {}};
        if (r.ok) {
            for (int i = 0; i < kAxisCount; ++i)
                joints.series.push_back({"joint " + comparisonAxisNames()[static_cast<size_t>(i)],
                                         chartColor(i), r.trace.t_s,
                                         r.trace.joint_error_deg[static_cast<size_t>(i)], false});
            for (int k = 0; k < 3; ++k)
                tip.series.push_back({kXyz[k], chartColor(k), r.trace.t_s,
                                      r.trace.tip_error_mm[static_cast<size_t>(k)], false});
        } else {
            joints.title += " (not simulated)";
            tip.title += " (not simulated)";
        }
        out.emplace_back("joint_errors_" + suffix, std::move(joints));
        out.emplace_back("tip_errors_" + suffix, std::move(tip));
    }
    // Fig. 11, 12 first, then 13, 14, as the paper orders them.
    std::swap(out[1], out[2]);
    LineChart max{"Max |joint error| per joint", "joint", "max |commanded - actual| (deg)", {}, {}};
    for (int i = 0; i < kAxisCount; ++i)
        max.x_categories.push_back(comparisonAxisNames()[static_cast<size_t>(i)]);
    for (size_t m = 0; m < 2; ++m) {
        const MethodRun& r = c.runs[m];
        ChartSeries s{methodTitle(r.method), chartColor(static_cast<int>(m) * 3), {}, {}, true};
        for (int i = 0; i < kAxisCount; ++i) {
            s.x.push_back(i);
            s.y.push_back(r.ok ? r.trace.joint_max_abs_deg[static_cast<size_t>(i)] : kNaN);
        }
        max.series.push_back(std::move(s));
    }
    out.emplace_back("max_joint_error", std::move(max));
    return out;
}

// PipeRobotModule's comparison (declared in pipe_robot_module.h, defined beside its work).
Outcome PipeRobotModule::compareMethods(const Job& job, MethodComparisonFiles* out) const {
    const MethodComparison c = runMethodComparison(job);
    out->json = json::write(comparisonJson(c));
    out->markdown = comparisonMarkdown(c);
    out->charts = comparisonCharts(c);
    if (c.ok()) return Outcome::done();
    std::string why;
    for (const MethodRun& r : c.runs)
        if (!r.ok)
            why += (why.empty() ? "" : "; ") + std::string(toString(r.method)) + ": " + r.problem;
    return Outcome::incomplete("not every method could be simulated: " + why, "machine.method");
}

} // namespace cutcell
