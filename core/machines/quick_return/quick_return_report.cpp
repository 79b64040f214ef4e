// The offline report of the quick-return cutter: both experiments of seed 004 for the four
// controllers, with the job's controller's traces for the plots.
#include "core/common/c_format.h"
#include "core/machines/quick_return/paper_parameters.h"
#include "core/machines/quick_return/quick_return_module.h"

#include <cmath>

namespace cutcell {

using namespace quick_return;

namespace {

double finite(double v) {
    return std::isfinite(v) ? v : 0;
}

json::Value traceJson(const std::vector<TracePoint>& tr) {
    json::Array t, y, dy, yd, dyd, tau;
    for (const TracePoint& p : tr) {
        t.emplace_back(finite(p.t));
        y.emplace_back(finite(p.y));
        dy.emplace_back(finite(p.dy));
        yd.emplace_back(finite(p.y_d));
        dyd.emplace_back(finite(p.dy_d));
        tau.emplace_back(finite(p.torque));
    }
    return json::Object{{"t_s", t},    {"y_m", y},        {"dy_m_s", dy},
                        {"y_d_m", yd}, {"dy_d_m_s", dyd}, {"torque_nm", tau}};
}

json::Value cycleJson(const LimitCycle& c) {
    return json::Object{{"limit_cycle", c.detected},
                        {"frequency_hz", finite(c.frequency_hz)},
                        {"amplitude", finite(c.amplitude)},
                        {"amplitude_early", finite(c.amplitude_early)},
                        {"amplitude_late", finite(c.amplitude_late)},
                        {"periodicity", finite(c.periodicity)},
                        {"verdict", c.verdict}};
}

json::Value runJson(const Experiment1Run& r) {
    return json::Object{{"controller", toString(r.controller)},
                        {"osmc_k2", finite(r.k2)},
                        {"mse", finite(r.mse)},
                        {"max_abs_error_m", finite(r.max_abs_error)},
                        {"max_torque_nm", finite(r.max_torque)},
                        {"singular_passes", r.singular_passes},
                        {"crank_turns", finite(r.crank_turns)},
                        {"error_m", cycleJson(r.error_cycle)},
                        {"sliding_variable_m_s", cycleJson(r.sliding_cycle)}};
}

// One row: MSE, max |e|, and the detector on e (mm) and on s / c2 (mm/s).
std::string runRow(const char* name, const Experiment1Run& r) {
    const auto cycle = [](const LimitCycle& c) {
        return formatC("%-3s %8.3f %10.3f %6.2f", c.detected ? "yes" : "no", c.frequency_hz,
                       1000 * c.amplitude_late, c.ratio());
    };
    return formatC("%-10s %12.5f %10.3f %6d %7.1f   %s   %s\n", name, r.mse, 1000 * r.max_abs_error,
                   r.singular_passes, r.crank_turns, cycle(r.error_cycle).c_str(),
                   cycle(r.sliding_cycle).c_str());
}

} // namespace

std::string experiment1StudyText(const Experiment1Study& st, const ExperimentSetup& s) {
    const LimitCycleOptions o = experiment1CycleOptions(s);
    std::string forced;
    for (const double f : o.forced_hz)
        forced += formatC("%s%.4g", forced.empty() ? "" : ", ", f);
    std::string t = formatC(
        "\nexperiment 1 study: limit cycle (LC) over the last %.1f s: e, or s/c2 = slope e + e', "
        "less the forced %s Hz and their harmonics up to %d, is periodic "
        "(autocorrelation at least %.2f at the period), late/early amplitude (ratio, sqrt(2) rms) "
        "at least %.2f, above half a scale count; passes: the crank through its singular "
        "points, turns: its net turns\n",
        o.window_s, forced.c_str(), o.forced_harmonics, o.min_periodicity, o.sustain_ratio);
    const std::string head =
        formatC("%-10s %12s %10s %6s %7s   %-3s %8s %10s %6s   %-3s %8s %10s %6s\n", "ctrl", "MSE",
                "max|e| mm", "passes", "turns", "LC", "e Hz", "e amp mm", "ratio", "LC", "s Hz",
                "s mm/s", "ratio");
    t += head;
    for (const Experiment1Run& r : st.runs)
        t += runRow(toString(r.controller), r);
    for (const Experiment1Run& r : st.runs)
        t += formatC("  %s: e: %s; s: %s\n", toString(r.controller), r.error_cycle.verdict.c_str(),
                     r.sliding_cycle.verdict.c_str());
    if (!st.sweep_skipped.empty()) return t + "k2 sweep not run: " + st.sweep_skipped + "\n";
    t += formatC("\nOSMC k2 sweep at k1 = %.6g (to beat FFC and LQT: MSE below %.5f)\n", st.k1,
                 st.rival_mse);
    t += head;
    for (const Experiment1Run& r : st.sweep)
        t += runRow(formatC("k2=%.4g", r.k2).c_str(), r);
    if (!st.osmc_wins)
        t += formatC("no k2 of the sweep beats FFC and LQT (best OSMC MSE %.5f)\n",
                     std::min_element(st.sweep.begin(), st.sweep.end(),
                                      [](const Experiment1Run& a, const Experiment1Run& b) {
                                          return a.mse < b.mse;
                                      })
                         ->mse);
    else
        t += formatC("smallest winning k2 of the sweep: %.4g (threshold between %.4g and %.4g)\n",
                     st.smallest_k2, st.threshold_lo, st.threshold_hi);
    return t;
}

json::Value experiment1StudyJson(const Experiment1Study& st, const ExperimentSetup& s) {
    const LimitCycleOptions o = experiment1CycleOptions(s);
    json::Array runs, sweep, forced;
    for (const double f : o.forced_hz)
        forced.emplace_back(finite(f));
    for (const Experiment1Run& r : st.runs)
        runs.emplace_back(runJson(r));
    for (const Experiment1Run& r : st.sweep)
        sweep.emplace_back(runJson(r));
    const json::Value detector = json::Object{{"window_s", finite(o.window_s)},
                                              {"forced_hz", forced},
                                              {"forced_harmonics", o.forced_harmonics},
                                              {"min_periodicity", finite(o.min_periodicity)},
                                              {"sustain_ratio", finite(o.sustain_ratio)},
                                              {"error_floor_m", finite(0.5 * s.scale_resolution)}};
    return json::Object{{"detector", detector},
                        {"controllers", runs},
                        {"osmc_k1", finite(st.k1)},
                        {"rival_mse", finite(st.rival_mse)},
                        {"k2_sweep", sweep},
                        {"sweep_skipped", st.sweep_skipped},
                        {"osmc_wins", st.osmc_wins},
                        {"smallest_winning_k2", finite(st.smallest_k2)},
                        {"threshold_k2_lo", finite(st.threshold_lo)},
                        {"threshold_k2_hi", finite(st.threshold_hi)}};
}

json::Value quickReturnReport(const QuickReturnSpec& spec, const ExperimentSetup& s,
                              std::string* table) {
    const StrokeInfo& st = s.law.stroke;
    const VelocityProfile& p = s.law.profile;
    const OsmcSurface surf = osmcSurface(s.law.gains);
    std::string t =
        formatC("mechanism: q_top %.5f rad (y_min %.5f m), q_bottom %.5f rad (y_max "
                "%.5f m), stroke %.5f m, cut arc %.4f rad, return arc %.4f rad\n",
                st.q_top, st.y_top, st.q_bottom, st.y_bottom, st.stroke, st.cut_arc, st.return_arc);
    t += formatC("Algorithm 1 (v = %.4f m/s, L_d = %.4f m): t_c %.4f s, t_a = t_d %.4f s, y_a "
                 "%.5f m, y_b %.5f m\n",
                 p.v, p.l_d, p.t_c, p.t_a, p.y_a, p.y_b);
    t += formatC("OSMC surface s = %.6g e + %.6g e' (slope %.4f 1/s), ARE residual %.3g\n", surf.c1,
                 surf.c2, surf.slope(), surf.residual);
    t += formatC("\nexperiment 1: y_d = %.3f + %.3f sin(%.4f t), %.1f s, MSE of L e over the "
                 "last %.1f s (L = %g)\n",
                 spec.track_offset, spec.track_amplitude, spec.track_omega, spec.track_duration,
                 spec.mse_window, spec.mse_scale);
    t += formatC("%-6s %12s %14s %14s\n", "ctrl", "MSE", "max |e| (mm)", "max |tau| (Nm)");
    json::Array exp1, exp2;
    json::Value traces = json::Object{};
    for (ControllerKind k : kAllControllers) {
        const TrackingResult r = runTracking(s, k);
        t += formatC("%-6s %12.5f %14.4f %14.2f\n", toString(k), r.mse, 1000 * r.max_abs_error,
                     r.max_torque);
        exp1.emplace_back(json::Object{{"controller", toString(k)},
                                       {"mse", finite(r.mse)},
                                       {"max_abs_error_m", finite(r.max_abs_error)},
                                       {"max_torque_nm", finite(r.max_torque)}});
        if (k == spec.controller) traces.set("tracking", traceJson(r.trace));
    }
    t += formatC("\nexperiment 2: %d strokes with %.0f N contact force, velocity error over the "
                 "workpiece [%.4f, %.4f] m\n",
                 spec.strokes, s.plant.contact_force, std::min(p.y_a, p.y_b),
                 std::max(p.y_a, p.y_b));
    t += formatC("%-6s %9s %14s %14s %14s %10s\n", "ctrl", "strokes", "max (m/s)", "rms (m/s)",
                 "max |tau| (Nm)", "return (s)");
    for (ControllerKind k : kAllControllers) {
        const CuttingResult r = runCutting(s, k);
        t += formatC("%-6s %9d %14.4f %14.4f %14.2f %10.3f%s%s\n", toString(k), r.strokes,
                     r.velocity_error_max, r.velocity_error_rms, r.max_torque, r.return_time,
                     r.completed ? "" : "  NOT COMPLETED: ", r.problem.c_str());
        exp2.emplace_back(json::Object{{"controller", toString(k)},
                                       {"completed", r.completed},
                                       {"problem", r.problem},
                                       {"strokes", r.strokes},
                                       {"velocity_error_max_m_s", finite(r.velocity_error_max)},
                                       {"velocity_error_rms_m_s", finite(r.velocity_error_rms)},
                                       {"samples_in_work", r.samples_in_work},
                                       {"max_torque_nm", finite(r.max_torque)},
                                       {"cycle_time_s", finite(r.cycle_time)},
                                       {"return_time_s", finite(r.return_time)}});
        if (k == spec.controller) traces.set("cutting", traceJson(r.trace));
    }
    *table = t;
    return json::Object{{"machine", kQuickReturnId},
                        {"mechanism", json::Object{{"q_top_rad", st.q_top},
                                                   {"q_bottom_rad", st.q_bottom},
                                                   {"y_min_m", st.y_top},
                                                   {"y_max_m", st.y_bottom},
                                                   {"stroke_m", st.stroke},
                                                   {"cut_arc_rad", st.cut_arc},
                                                   {"return_arc_rad", st.return_arc},
                                                   {"max_abs_rho_y_cut_m", st.max_abs_rho_y_cut}}},
                        {"profile", json::Object{{"v_m_s", p.v},
                                                 {"t_c_s", p.t_c},
                                                 {"t_a_s", p.t_a},
                                                 {"y_a_m", p.y_a},
                                                 {"y_b_m", p.y_b}}},
                        {"osmc_surface", json::Object{{"c1", surf.c1},
                                                      {"c2", surf.c2},
                                                      {"slope_1_s", surf.slope()},
                                                      {"riccati_p", surf.p},
                                                      {"riccati_residual", surf.residual}}},
                        {"experiment1_tracking", exp1},
                        {"experiment2_cutting", exp2},
                        {"traces_of_" + std::string(toString(spec.controller)), traces}};
}

} // namespace cutcell
