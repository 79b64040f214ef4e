#include "core/machines/section_steel/section_steel_module.h"

#include "core/machine/parameter_level.h"

#include "core/common/c_format.h"
#include "core/job/default_job.h"
#include "core/job/issue_checker.h"
#include "core/machines/section_steel/dstv/dstv_import.h"
#include "core/machines/section_steel/end_cut_path.h"
#include "core/machines/section_steel/section_kerf.h"
#include "core/machines/section_steel/section_lead.h"
#include "core/machines/section_steel/section_steel_planner.h"
#include "core/machines/section_steel/section_steel_program.h"
#include "core/machines/section_steel/section_steel_section.h"
#include "core/process/process_spec.h"
#include "core/sim/tracking_stats.h"

#include <algorithm>

namespace cutcell {

using namespace section_steel;

namespace {

const SectionSteelSpec& specOf(const Job& job) {
    const SectionSteelSpec* s = job.machine_spec.as<SectionSteelSpec>();
    if (!s) throw std::invalid_argument("the job holds no section-steel machine section");
    return *s;
}

const char* const kAxisNames[kSteelAxes] = {"path theta1",   "path theta2",   "path theta3",
                                            "groove theta1", "groove theta2", "groove theta3",
                                            "groove theta4", "groove theta5"};

} // namespace

std::vector<AxisInfo> SectionSteelModule::axes(const Job& job) const {
    const SectionSteelSpec& s = specOf(job);
    std::vector<AxisInfo> out;
    for (size_t i = 0; i < 3; ++i)
        out.push_back({kAxisNames[i], AxisUnit::Rotary, s.path_limits[i].min_deg,
                       s.path_limits[i].max_deg, CommandMode::Position});
    for (size_t i = 0; i < 5; ++i)
        out.push_back({kAxisNames[3 + i], AxisUnit::Rotary, s.groove_limits[i].min_deg,
                       s.groove_limits[i].max_deg, CommandMode::Position});
    return out;
}

Job SectionSteelModule::defaultJob() const {
    Job job = cutcell::defaultJob();
    job.machine = kSectionSteelId;
    job.name = "Seed 001 - IPE 300 square end";
    job.description =
        "Section-steel cutting cell of seed 001 (Xu): a 3R cutting-path arm (links 1000, 1110, "
        "310 mm) working in the square cut plane, its base 1500 mm above the table on the bar "
        "axis, and a 5-DOF groove arm (modified DH) beside the bar end (base 120 mm past the cut, "
        "900 mm to the side, 700 mm high; its 2R arm in a plane parallel to the cut plane, the "
        "bevel head "
        "tilting the torch about the nozzle). The bar lies on the table along x, web vertical; "
        "the path arm cuts the square end round the outline, the groove arm bevels face by face. "
        "The seed gives no layout: this one is a plausible design.";
    job.machine_spec.set(defaultSectionSteelSpec());
    job.sim.duration_s = 1; // the run lasts the program (at least 1 s)
    return job;
}

void SectionSteelModule::readSection(const json::Value& section, Job& job) const {
    SectionReader m(section, "machine");
    m.get("kind");
    job.machine_spec.set(readSteelSection(m));
    // The torch's process (cut chart entry, overrides), as the pipe machines read it: here it
    // gives the kerf to compensate (section_kerf.h); the speed stays motion.speed_mm_s.
    readProcess(m, job.process);
    m.finish();
}

json::Value SectionSteelModule::writeSection(const Job& job) const {
    json::Object s{{"kind", id()}};
    writeSteelSection(specOf(job), s);
    // The process section after the section and its piece marks (what is cut, and with what).
    json::Object process;
    writeProcess(job.process, process);
    if (!process.empty()) {
        const auto at = std::find_if(s.begin(), s.end(), [](const auto& member) {
            return member.first != "kind" && member.first != "section" && member.first != "piece";
        });
        s.insert(at, std::move(process.front()));
    }
    return s;
}

std::vector<JobIssue> SectionSteelModule::validate(const Job& job) const {
    IssueChecker c;
    const SectionSteelSpec& s = specOf(job);
    checkSteelSpec(c, s, job.sim.period_s);
    checkProcess(c, job.process, steelPartThicknessMm(s));
    checkNoTorchHeight(c, job.process, "section-steel cutter");
    // Leads (section_lead.h): checkProcess has checked the heights (leadHeightProblem); the
    // cut's open ends and setup 2 here.
    if (const SteelLeadRequest leads = steelLeadRequest(job);
        !leads.problem.empty() && !c.has(leads.problem_key))
        c.add(leads.problem_key, leads.problem);
    // The cut chart gives this machine its kerf only: any other override would be ignored.
    if (const auto v = job.process.override.get(CutFigure::CutSpeedMmMin); job.process.used && v)
        c.add("process.override.cut_speed_mm_min",
              messageC("process.override.cut_speed_mm_min = %.6g mm/min is not used by the "
                       "section-steel cutter: it cuts at motion.speed_mm_s = %.6g mm/s (its "
                       "process section gives the kerf); set the speed there",
                       *v, s.speed_mm_s));
    for (std::size_t i = 0; i < kCutFigureCount && job.process.used; ++i) {
        const auto f = static_cast<CutFigure>(i);
        if (f == CutFigure::KerfMm || f == CutFigure::CutSpeedMmMin) continue;
        // The heights are the leads' (section_lead.h).
        const bool leads = job.process.lead_in.used() || job.process.lead_out.used();
        if (leads && (f == CutFigure::PierceHeightMm || f == CutFigure::CutHeightMm)) continue;
        if (const auto v = job.process.override.get(f)) {
            const CutFigureInfo& info = cutFigureInfo(f);
            c.add(std::string("process.override.") + info.key,
                  messageC("process.override.%s = %.6g %s is not used by the section-steel "
                           "cutter (its process section gives the kerf only); remove it",
                           info.key, *v, info.unit));
        }
    }
    return c.issues;
}

Outcome SectionSteelModule::canOpen() const {
    return Outcome::done(); // CiA 402 drives (and CiA 406 encoders): devices/machines/can_cells.cpp
}

MachinePlan SectionSteelModule::plan(const Job& job, const std::string& jobText,
                                     const PlanOptions& /*options: plans in one go*/) const {
    MachinePlan out;
    const SectionSteelSpec& s = specOf(job);
    if (const std::string why = setupTwoProblem(s); !why.empty()) {
        out.outcome = Outcome::refuse(why); // never an empty run
        out.summary = why;
        return out;
    }
    // Leads asked for where they cannot be (refused below): the cut without them, for the view.
    const SteelLeadRequest leads = steelLeadRequest(job);
    auto plan = std::make_shared<SteelPlan>(planEndCut(s, steelKerfMm(job), leads.spec));
    out.data = plan;
    const std::string name = s.section.designation.empty()
                                 ? std::string("user-defined ") + toString(s.section.family)
                                 : s.section.designation;
    std::string passes;
    for (const auto& p : plan->passes)
        passes += (passes.empty() ? "" : " + ") + p.name +
                  (p.groove_arm ? " (groove arm)" : " (path arm)");
    out.summary = formatC("%s, mitre %.1f/%.1f deg, %s, %.1f mm at %.2f mm/s (%.1f s)",
                          name.c_str(), s.cut.mitre_vertical_deg, s.cut.mitre_horizontal_deg,
                          passes.c_str(), plan->length_mm, s.speed_mm_s, plan->cut_time_s);
    // The face on the conveyor is not in setup 1's outline: a K groove there gets its second
    // bevel in setup 2, after the operator has turned the section over.
    const char* plate = s.section.family == SectionFamily::L ? "horizontal leg" : "bottom flange";
    if (s.cut.setup == 1 && s.cut.flanges.type == GrooveType::K)
        out.summary += formatC("; setup 1 of 2: K groove - the underside of the %s (on the "
                               "conveyor) is not bevelled here: turn the section over (180 deg "
                               "about its long axis) and plan setup 2 (end_cut.setup = 2)",
                               plate);
    if (s.cut.setup == 2)
        out.summary = formatC("setup 2 of 2 (section turned over 180 deg about its long axis, the "
                              "underside of the %s on top; mitres in the cell %.1f/%.1f deg): ",
                              plate, -s.cut.mitre_vertical_deg, -s.cut.mitre_horizontal_deg) +
                      out.summary;
    if (plan->kerf_mm > 0)
        out.summary += formatC("; kerf %.2f mm compensated (the torch centre %.3f mm across the "
                               "cut surface off the edge; the arms' frame %.3f mm along the bar "
                               "toward the off-cut)",
                               plan->kerf_mm, plan->kerf_mm / 2, plan->frame_shift_mm);
    if (plan->leads_added) {
        const SteelLeadSpec& l = leads.spec;
        out.summary += formatC("; edge start, fired at pierce height %.2f mm, down to cut height "
                               "%.2f mm",
                               l.pierce_height_mm, l.cut_height_mm);
        if (l.in.used())
            out.summary += formatC("; lead-in %s %.1f mm", toString(l.in.kind), l.in.length_mm);
        if (l.out.used())
            out.summary += formatC("; lead-out %s %.1f mm", toString(l.out.kind), l.out.length_mm);
    }
    if (!leads.problem.empty()) {
        out.outcome = Outcome::refuse(leads.problem, leads.problem_key);
        return out;
    }
    if (!plan->lead_problem.empty()) {
        out.outcome = Outcome::refuse(plan->lead_problem, plan->lead_key);
        return out;
    }
    if (!plan->kerf_problem.empty()) {
        out.outcome = Outcome::refuse(plan->kerf_problem, "process.override.kerf_mm");
        return out;
    }
    if (!plan->ok) {
        out.outcome = Outcome::refuse(plan->failed_points > 1
                                          ? messageC("%s (and %zu more points)",
                                                     plan->problem.c_str(), plan->failed_points - 1)
                                          : plan->problem);
        return out;
    }
    out.program = buildSectionSteelProgram(job, s, *plan, jobText);
    out.outcome = Outcome::done();
    return out;
}

std::vector<ExportInfo> SectionSteelModule::exports() const {
    return {
        {"path_csv", "torch path with torch directions and joints (CSV)", "path.csv", true, false}};
}

std::string SectionSteelModule::exportFile(const std::string& exportId, const Job& job,
                                           const MachinePlan& plan) const {
    const SteelPlan* p = static_cast<const SteelPlan*>(plan.data.get());
    if (!p || !plan.ok()) throw std::invalid_argument("the plan has no feasible cut");
    if (exportId == "path_csv") return steelPathCsv(specOf(job), *p);
    throw std::invalid_argument("the section-steel cutter has no export " + json::quote(exportId));
}

std::vector<JobImporter> SectionSteelModule::importers() const {
    return {dstvImporter()};
}

json::Value SectionSteelModule::runReport(const Job&, const MachinePlan& plan,
                                          const TrackingReport& report) const {
    std::array<std::string, kMaxAxes> names{};
    for (size_t i = 0; i < kSteelAxes; ++i)
        names[i] = kAxisNames[i];
    (void)plan;
    return reportToJson(report, &names);
}

bool SectionSteelModule::isMachineParameter(const std::string& key) const {
    return keyUnder(key, {"path_arm", "groove_arm", "park_deg", "drives", "motion.torch_length_mm",
                          "motion.torch_radius_mm", "motion.max_lean_deg"});
}

} // namespace cutcell
