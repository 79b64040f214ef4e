#include "core/machines/flying_saw/flying_saw_module.h"

#include "core/machine/parameter_level.h"

#include "core/common/c_format.h"
#include "core/job/default_job.h"
#include "core/machines/flying_saw/flying_saw_program.h"
#include "core/machines/flying_saw/flying_saw_section.h"
#include "core/machines/flying_saw/saw_csv.h"
#include "core/machines/flying_saw/saw_simulation.h"
#include "core/sim/tracking_stats.h"

#include <chrono>
#include <stdexcept>

namespace cutcell {

const FlyingSawSpec& flyingSawSpec(const Job& job) {
    const FlyingSawSpec* s = job.machine_spec.as<FlyingSawSpec>();
    if (!s)
        throw JobError("the job holds no flying-saw section (machine.kind = " +
                       json::quote(job.machine) + ")");
    return *s;
}

std::vector<AxisInfo> FlyingSawModule::axes(const Job& job) const {
    const FlyingSawSpec* s = job.machine_spec.as<FlyingSawSpec>();
    const double stroke = s ? s->stroke_mm : 2500;
    double feedMax = 100;
    if (s) {
        const TubeOutline o = outerOutline(*s);
        feedMax = o.maxRadius() + s->saw.clearance_mm;
    }
    return {{"carriage", AxisUnit::Linear, 0, stroke, CommandMode::Position},
            {"turntable", AxisUnit::Rotary, -1e9, 1e9, CommandMode::Position},
            {"feed 1", AxisUnit::Linear, 0, feedMax, CommandMode::Position},
            {"feed 2", AxisUnit::Linear, 0, feedMax, CommandMode::Position}};
}

RunTerms FlyingSawModule::runTerms() const {
    return flyingSawTerms();
}

Job FlyingSawModule::defaultJob() const {
    // Only the common part (sim, engine, devices) of the built-in job: none of the pipe
    // robot's fields, which this machine's section neither reads nor writes.
    const Job common = cutcell::defaultJob();
    Job job;
    job.sim = common.sim;
    job.engine = common.engine;
    // The drives reach a set-point one period after it is written: at 1 m/s that alone is 1 mm
    // of "error"; the carriage's lag in its ramps adds about as much.
    job.engine.following_error_limit_mm = 10;
    job.devices = common.devices;
    job.machine = kFlyingSawId;
    job.name = "New flying saw job";
    job.description = "Square tube 60 x 60 x 2 mm (corner radius 4 mm), 6 m pieces at 60 m/min";
    FlyingSawSpec s;
    s.queue = {{6000, 10}};
    job.machine_spec.set(s);
    job.sim.period_s = 0.001;
    job.sim.duration_s = 120;
    return job;
}

void FlyingSawModule::readSection(const json::Value& section, Job& job) const {
    job.machine_spec.set(readFlyingSawSection(section));
}

json::Value FlyingSawModule::writeSection(const Job& job) const {
    json::Object s{{"kind", id()}};
    for (auto& kv : writeFlyingSawSection(flyingSawSpec(job)))
        s.push_back(std::move(kv));
    return s;
}

void FlyingSawModule::migrateSchema1(json::Object&) const {
    // The flying saw came after schema 2: a schema-1 file never named it.
}

std::vector<JobIssue> FlyingSawModule::validate(const Job& job) const {
    const FlyingSawSpec* s = job.machine_spec.as<FlyingSawSpec>();
    if (!s) return {{"kind", "the job holds no flying-saw section"}};
    return checkFlyingSawSpec(*s);
}

Outcome FlyingSawModule::canOpen() const {
    return Outcome::done(); // CiA 402 drives + the line's CiA 406 encoder:
                            // devices/machines/can_cells.cpp
}

MachinePlan FlyingSawModule::plan(const Job& job, const std::string& jobText,
                                  const PlanOptions& /*options: plans in one go*/) const {
    MachinePlan out;
    auto data = std::make_shared<FlyingSawPlanData>();
    data->spec = flyingSawSpec(job);
    data->plan = planFlyingSaw(data->spec);
    out.data = data;
    const FlyingSawPlan& p = data->plan;
    const FlyingSawSpec& s = data->spec;
    if (!p.ok) {
        out.outcome =
            Outcome::refuse(messageC("not feasible: machine.%s", p.problem.c_str()), p.problemKey);
        out.summary = p.problem;
        return out;
    }
    out.summary = messageC(
        "%d pieces at %.4g m/min; cycle %.2f s (sync-in %.3f s, sync + cut %.3f s, decel %.3f s, "
        "return %.3f s at k = %.2f); stroke %.0f of %.0f mm; shortest piece %.0f mm",
        s.pieceCount(), s.line_speed_m_min, p.cycle_time_s, p.T1, p.T2, p.T3,
        p.nominal_reverse.duration(), p.k, p.stroke_needed_mm, s.stroke_mm, p.shortest_length_mm);
    out.program = buildFlyingSawProgram(job, s, p, jobText);
    out.outcome = Outcome::done();
    return out;
}

std::vector<ExportInfo> FlyingSawModule::exports() const {
    return {
        {"cam_csv", "saw cam table: turntable angle, feed (CSV)", "cam.csv", true, false},
        {"cycle_csv", "carriage cycle s, v, a with the periods (CSV)", "cycle.csv", true, false},
        {"pieces_csv", "simulated cut length of every piece (CSV)", "pieces.csv", true, false}};
}

std::string FlyingSawModule::exportFile(const std::string& exportId, const Job&,
                                        const MachinePlan& plan) const {
    const auto* data = static_cast<const FlyingSawPlanData*>(plan.data.get());
    if (!data || !data->plan.ok) throw std::invalid_argument("the plan is not feasible");
    if (exportId == "cam_csv") return camTableCsv(data->plan);
    if (exportId == "cycle_csv") return cycleCsv(data->plan);
    if (exportId == "pieces_csv") {
        if (const std::string over = sawSimWorkProblem(data->spec, data->plan); !over.empty())
            throw std::invalid_argument(over);
        return piecesCsv(simulateFlyingSaw(data->spec, data->plan));
    }
    throw std::invalid_argument("the flying saw has no export " + json::quote(exportId));
}

Outcome FlyingSawModule::offlineReport(const Job& job, const MachinePlan& plan, std::string* json,
                                       std::string* text) const {
    const auto* data = static_cast<const FlyingSawPlanData*>(plan.data.get());
    if (!data || !plan.ok()) return Outcome::refuse(plan.outcome.message);
    SawSimOptions o;
    o.period_s = job.sim.period_s;
    if (const std::string over = sawSimWorkProblem(data->spec, data->plan, o); !over.empty())
        return Outcome::refuse(over, "machine.queue");
    const SawSimResult r = simulateFlyingSaw(data->spec, data->plan, o);
    *json = sawReportJson(data->spec, data->plan, r);
    *text = sawReportText(data->spec, data->plan, r);
    if (!r.completed) return Outcome::incomplete(messageC("NOT completed: %s", r.problem.c_str()));
    return Outcome::done();
}

void FlyingSawModule::addBenchFigures(bool, json::Object& out) const {
    FlyingSawSpec s; // the defaults: 60 m/min, wander 2 % at 0.1 Hz, 1 % steps, 0.05 mm
    s.queue = {{6000, 200}};
    s.stroke_mm = 4000;
    s.line_sim.slip_fraction = 0;
    s.gauge_enabled = false; // the encoder and the carriage alone
    const FlyingSawPlan p = planFlyingSaw(s);
    if (!p.ok) return;
    const auto t0 = std::chrono::steady_clock::now();
    const SawSimResult r = simulateFlyingSaw(s, p);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.emplace_back("saw_pieces", r.stats.count);
    out.emplace_back("saw_cut_length_error_mm_mean", r.stats.mean);
    out.emplace_back("saw_cut_length_error_mm_std", r.stats.std);
    out.emplace_back("saw_cut_length_error_mm_max_abs", r.stats.max_abs);
    out.emplace_back("saw_cut_length_cpk", r.stats.cpk);
    out.emplace_back("saw_cut_spread_mm_max", [&] {
        double m = 0;
        for (const PieceRecord& pr : r.pieces)
            m = std::max(m, pr.spread_mm);
        return m;
    }());
    out.emplace_back("saw_simulated_seconds", r.simulated_s);
    out.emplace_back("saw_simulation_seconds", wall);
    s.gauge_enabled = true; // the same with the length gauge correcting the scale
    const SawSimResult g = simulateFlyingSaw(s, p);
    out.emplace_back("saw_cut_length_error_mm_std_with_gauge", g.stats.std);
    out.emplace_back("saw_cut_length_error_mm_max_abs_with_gauge", g.stats.max_abs);
}

json::Value FlyingSawModule::runReport(const Job&, const MachinePlan& plan,
                                       const TrackingReport& report) const {
    std::array<std::string, kMaxAxes> names{};
    if (plan.program) names = plan.program->axis_names;
    json::Value doc = reportToJson(report, &names);
    doc.set("machine", kFlyingSawId);
    return doc;
}

bool FlyingSawModule::isMachineParameter(const std::string& key) const {
    return keyUnder(key,
                    {"line.roller_pulses_per_rev", "line.roller_diameter_mm", "line.filter_alpha",
                     "carriage", "saw.settle_s", "saw.clearance_mm", "saw.turntable_deg_s",
                     "saw.turntable_deg_s2", "saw.table_points", "gauge", "line_sim"});
}

} // namespace cutcell
