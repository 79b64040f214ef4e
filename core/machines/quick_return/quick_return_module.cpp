#include "core/machines/quick_return/quick_return_module.h"

#include "core/machine/parameter_level.h"

#include "core/common/c_format.h"
#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/machines/quick_return/quick_return_svg.h"
#include "core/machines/quick_return/task_controllers.h"
#include "core/sim/tracking_stats.h"

#include <cmath>
#include <numbers>

namespace cutcell {

using namespace quick_return;

std::vector<AxisInfo> QuickReturnModule::axes(const Job&) const {
    // The crank turns without end: no travel limits.
    return {{"crank", AxisUnit::Rotary, -1e9, 1e9, CommandMode::Torque}};
}

RunTerms QuickReturnModule::runTerms() const {
    // The slider's cutter makes strokes; the run has no path length.
    RunTerms t;
    t.tool = "cutter";
    t.process_ok = "cutter ready";
    t.process_lost = "cutter lost";
    t.counts = WorkCount::Strokes;
    t.path_length = false;
    return t;
}

Job QuickReturnModule::defaultJob() const {
    Job job = cutcell::defaultJob();
    job.machine = kQuickReturnId;
    job.name = "New quick-return cutter job";
    job.description =
        "Seed 004 cutting task on a consistent mechanism: O3 = (0.085, 0) m, r2 = 0.122 m, "
        "AB = 0.1215 m, r4 = 0.366 m, Dx = -0.061 m turns fully with a stroke of 0.4665 m "
        "(fits L_c = 0.4667 m) and L_d = 0.3 m; the seed's printed dimensions do not close.";
    job.machine_spec.set(QuickReturnSpec{});
    // The crank's following error is the slider's divided by rho_y (~0.1 m/rad over the
    // work): the 400 N impact on the workpiece lags the crank ~2 deg, so 2 deg would trip.
    job.engine.following_error_limit_deg = 10;
    // Normalised through the file form: the common Job's pipe and robot fields, which this
    // machine does not keep, take the values a saved and reopened job has.
    return jobFromJson(jobToJson(job));
}

void QuickReturnModule::readSection(const json::Value& section, Job& job) const {
    job.machine_spec.set(readQuickReturnSection(section));
}

json::Value QuickReturnModule::writeSection(const Job& job) const {
    return writeQuickReturnSection(quickReturnSpec(job), id());
}

void QuickReturnModule::migrateSchema1(json::Object& section) const {
    // Schema 1 knew no quick-return cutter: it made every job carry the pipe robot's keys,
    // which go. Anything else stays and is read as this machine's (or refused by name): a
    // hand-written file's mechanism.r2_m = -5 was dropped and the default loaded silently.
    const auto isCrankCut = [](const json::Value& cut) {
        if (!cut.isObject()) return false;
        for (const auto& [k, v] : cut.asObject())
            for (const auto& f : quickReturnFields())
                if (std::string(f.key) == "cut." + k) return true;
        return false;
    };
    std::erase_if(section, [&](const auto& kv) {
        const std::string& k = kv.first;
        if (k == "cut") return !isCrankCut(kv.second);
        return k == "main_pipe" || k == "branch_pipe" || k == "angle_deg" ||
               k == "eccentricity_mm" || k == "method" || k == "robot" || k == "controller" ||
               k == "plant" || k == "plant_model" || k == "gravity_feedforward" ||
               k == "other_branches" || k == "profile_cutter";
    });
}

std::vector<JobIssue> QuickReturnModule::validate(const Job& job) const {
    const QuickReturnSpec* s = job.machine_spec.as<QuickReturnSpec>();
    if (!s) return {{"machine", "the job holds no quick-return cutter section"}};
    return validateQuickReturn(*s);
}

Outcome QuickReturnModule::canOpen() const {
    return Outcome::done(); // CiA 402 drives (and CiA 406 encoders): devices/machines/can_cells.cpp
}

MachinePlan QuickReturnModule::plan(const Job& job, const std::string& jobText,
                                    const PlanOptions& /*options: plans in one go*/) const {
    MachinePlan out;
    const QuickReturnSpec& spec = quickReturnSpec(job);
    auto data = std::make_shared<QuickReturnPlanData>();
    if (const Outcome set = buildSetup(spec, &data->setup); !set.ok()) {
        out.outcome = Outcome::refuse(messageC("not feasible: %s", set.message.c_str()));
        return out;
    }
    const ExperimentSetup& s = data->setup;
    const StrokeInfo& st = s.law.stroke;
    const VelocityProfile& p = s.law.profile;
    auto law = std::make_shared<QuickReturnLaw>(s.law);
    auto prog = std::make_shared<MotionProgram>();
    prog->machine = id();
    prog->method = std::string(toString(spec.experiment)) + "/" + toString(spec.controller);
    prog->axis_count = 1;
    prog->axis_names[0] = "crank";
    prog->axis_linear[0] = false;
    prog->axis_continuous[0] = true; // the crank turns on: Home takes the short way
    prog->axis_modes[0] = AxisCommandMode::Torque;
    prog->source_kind = MotionSourceKind::ControlLaw;
    prog->source = law;
    const double q0 = spec.experiment == Experiment::Tracking
                          ? law->crankForSlider(spec.track_offset)
                          : st.q_bottom + 0.01;
    prog->reference[0] = q0;
    prog->start_position[0] = q0;
    // A turn of the crank a stroke (and one to come round to the first cut), from q0.
    const double turns = spec.experiment == Experiment::Tracking ? 1.0 : spec.strokes + 1.0;
    prog->endless_reach[0] = std::fabs(q0) + 2 * std::numbers::pi * turns;
    prog->sensors_used = 1u;
    prog->uses_tool = false;
    prog->point_count = static_cast<size_t>(spec.strokes);
    prog->terms = runTerms();
    prog->min_run_s = 0;
    prog->name = job.name;
    prog->source_text = jobText;
    out.program = prog;
    out.data = data;
    out.summary =
        formatC("%s with %s: stroke %.4f m (y_min %.4f, y_max %.4f m at q %.4f, %.4f rad), "
                "t_a %.4f s, t_c %.4f s, y_a %.4f m, y_b %.4f m",
                toString(spec.experiment), toString(spec.controller), st.stroke, st.y_top,
                st.y_bottom, st.q_top, st.q_bottom, p.t_a, p.t_c, p.y_a, p.y_b);
    out.outcome = Outcome::done();
    return out;
}

std::vector<ExportInfo> QuickReturnModule::exports() const {
    return {{"report_json", "both experiments, all controllers (JSON)", "quick_return.json", true,
             false},
            {"figures_svg", "mechanism, velocity profile, phase diagram, velocity error (SVG)",
             "quick_return_cut.svg", true, false}};
}

std::string QuickReturnModule::exportFile(const std::string& exportId, const Job& job,
                                          const MachinePlan& plan) const {
    const auto* data = static_cast<const QuickReturnPlanData*>(plan.data.get());
    if (!data) throw std::invalid_argument("the plan has no quick-return set-up");
    if (exportId == "figures_svg")
        return cuttingFiguresSvg(data->setup,
                                 runCutting(data->setup, quickReturnSpec(job).controller));
    if (exportId != "report_json")
        throw std::invalid_argument("the quick-return cutter has no export " +
                                    json::quote(exportId));
    std::string table;
    return json::write(quickReturnReport(quickReturnSpec(job), data->setup, &table));
}

// simulate runs both experiments for every controller at the sample time: a 1e-5 s sample time
// or 1000 strokes made minutes of work and a report of megabytes. Estimated first (a crank turn
// taken as the cutting branch's time scaled by the whole turn's arc over the cut arc: the
// return is quicker, so this errs high) and refused over the bound with the figures.
std::string QuickReturnModule::offlineWorkProblem(const QuickReturnSpec& spec,
                                                  const quick_return::ExperimentSetup& s) {
    const quick_return::StrokeInfo& st = s.law.stroke;
    const quick_return::VelocityProfile& p = s.law.profile;
    const double turn =
        st.cut_arc > 0 ? (p.t_c + 2 * p.t_a) * (st.cut_arc + st.return_arc) / st.cut_arc : 0;
    const double seconds = spec.track_duration + spec.strokes * turn;
    const double samples =
        static_cast<double>(quick_return::kAllControllers.size()) * seconds / spec.sample_time;
    if (samples <= kMaxOfflineSamples) return "";
    return messageC(
        "the offline simulation would compute about %.3g samples (%zu controllers x (%.1f s of "
        "tracking + %d strokes of about %.2f s) / control.sample_time_s = %.3g s), "
        "over the bound of %.3g samples: use a longer sample time or fewer strokes",
        samples, quick_return::kAllControllers.size(), spec.track_duration, spec.strokes, turn,
        spec.sample_time, kMaxOfflineSamples);
}

Outcome QuickReturnModule::offlineReport(const Job& job, const MachinePlan& plan, std::string* json,
                                         std::string* text) const {
    const auto* data = static_cast<const QuickReturnPlanData*>(plan.data.get());
    if (!data || !plan.ok()) return Outcome::refuse(plan.outcome.message);
    const QuickReturnSpec& spec = quickReturnSpec(job);
    if (const std::string over = offlineWorkProblem(spec, data->setup); !over.empty())
        return Outcome::refuse(over);
    json::Value report = quickReturnReport(spec, data->setup, text);
    // A job of experiment 1 gets its study: limit cycles and the OSMC's k2 sweep.
    if (spec.experiment == Experiment::Tracking) {
        const Experiment1Study st = studyExperiment1(data->setup, {}, kMaxOfflineSamples);
        *text += experiment1StudyText(st, data->setup);
        report.set("experiment1_study", experiment1StudyJson(st, data->setup));
    }
    *json = json::write(report);
    return Outcome::done();
}

json::Value QuickReturnModule::runReport(const Job&, const MachinePlan& plan,
                                         const TrackingReport& report) const {
    if (!plan.program) return reportToJson(report);
    return reportToJson(report, &plan.program->axis_names);
}

bool QuickReturnModule::isMachineParameter(const std::string& key) const {
    return keyUnder(key, {"mechanism", "slider", "crank_motor", "control"});
}

} // namespace cutcell
