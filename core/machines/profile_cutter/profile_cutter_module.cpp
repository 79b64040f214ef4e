#include "core/machines/profile_cutter/profile_cutter_module.h"
#include "core/process/process_spec.h"

#include "core/machine/parameter_level.h"

#include "core/common/c_format.h"
#include "core/job/default_job.h"
#include "core/job/issue_checker.h"
#include "core/machine/pipe_joint_section.h"
#include "core/machines/profile_cutter/gcode_export.h"
#include "core/machines/profile_cutter/profile_csv.h"
#include "core/machines/profile_cutter/profile_cutter_program.h"
#include "core/machines/profile_cutter/profile_cutter_section.h"
#include "core/pipe_joint/template_layout.h"
#include "core/pipe_joint/template_pdf.h"
#include "core/pipe_joint/template_svg.h"
#include "core/pipe_joint/template_tiles.h"

#include <cmath>
#include <optional>

namespace cutcell {
namespace {

// The torch stands radially over the pipe: no tilt, no static chuck angle, no start choice.
const CutKeys kCutKeys{true, false, false, false};

std::vector<OtherBranch> readOtherBranches(SectionReader& r) {
    std::vector<OtherBranch> out;
    const json::Value* m = r.get("other_branches");
    if (!m) return out;
    if (!m->isArray())
        throw JobError(r.key("other_branches") + " must be an array of branch pipes, found " +
                       m->typeName());
    if (m->asArray().size() > 16)
        throw JobError(r.key("other_branches") + " has " + std::to_string(m->asArray().size()) +
                       " pipes; the limit is 16");
    for (size_t i = 0; i < m->asArray().size(); ++i) {
        SectionReader b(m->asArray()[i], r.key("other_branches") + "[" + std::to_string(i) + "]");
        OtherBranch o;
        o.radius_mm = b.number("radius_mm", "mm");
        o.angle_deg = b.number("angle_deg", "deg");
        o.eccentricity_mm = b.number("eccentricity_mm", "mm", 0);
        o.position_mm = b.number("position_mm", "mm", 0);
        o.phase_deg = b.number("phase_deg", "deg", 0);
        b.finish();
        out.push_back(o);
    }
    return out;
}

} // namespace

std::vector<AxisInfo> ProfileCutterModule::axes(const Job& job) const {
    return {{"A (pipe turn)", AxisUnit::Rotary, -1e9, 1e9, CommandMode::Position},
            {"X (torch carriage)", AxisUnit::Linear, 0, profileCutterSpec(job).x_travel_mm,
             CommandMode::Position}};
}

Job ProfileCutterModule::defaultJob() const {
    // The shipped profile job's machine section over the default job's common part.
    Job job = cutcell::defaultJob();
    job.machine = kProfileCutterId;
    job.name = "New profile cutter job";
    job.description.clear();
    job.cut.target = CutTarget::Branch;
    job.cut.bevel_deg = 0;
    job.cut.speed_mm_s = 8;
    ProfileCutterSpec spec;
    spec.x_travel_mm = 1500;
    job.machine_spec.set(std::move(spec));
    job.sim.duration_s = 120;
    return job;
}

void ProfileCutterModule::readSection(const json::Value& section, Job& job) const {
    SectionReader m(section, "machine");
    m.get("kind");
    readPipeJoint(m, job, kCutKeys);
    ProfileCutterSpec spec;
    spec.other_branches = readOtherBranches(m);
    readFields(m, profileCutterFields(), spec);
    m.finish();
    job.machine_spec.set(std::move(spec));
}

json::Value ProfileCutterModule::writeSection(const Job& job) const {
    const ProfileCutterSpec& pc = profileCutterSpec(job);
    json::Object s{{"kind", id()}};
    writePipeJoint(job, s, kCutKeys);
    if (!pc.other_branches.empty()) {
        json::Array others;
        for (const auto& o : pc.other_branches)
            others.emplace_back(json::Object{{"radius_mm", o.radius_mm},
                                             {"angle_deg", o.angle_deg},
                                             {"eccentricity_mm", o.eccentricity_mm},
                                             {"position_mm", o.position_mm},
                                             {"phase_deg", o.phase_deg}});
        s.emplace_back("other_branches", others);
    }
    for (auto& [key, value] : writeFields(profileCutterFields(), pc))
        s.emplace_back(key, std::move(value));
    return s;
}

void ProfileCutterModule::migrateSchema1(json::Object& section) const {
    // Schema 1 made every job carry the robot's keys; this machine never read them.
    std::erase_if(section, [](const auto& kv) {
        return kv.first == "method" || kv.first == "robot" || kv.first == "controller" ||
               kv.first == "plant" || kv.first == "plant_model" ||
               kv.first == "gravity_feedforward";
    });
    for (auto& [k, v] : section) {
        if (k == "cut" && v.isObject())
            std::erase_if(v.asObject(), [](const auto& kv) {
                return kv.first == "max_direction_deviation_deg" ||
                       kv.first == "static_chuck_deg" || kv.first == "start_phi_deg";
            });
    }
}

std::vector<JobIssue> ProfileCutterModule::validate(const Job& job) const {
    IssueChecker c;
    checkPipeJoint(c, job, kCutKeys);
    checkNoTorchHeight(c, job.process, "profile cutter");
    const double R = job.main_pipe.radius_mm;
    const double a = deg2rad(job.angle_deg);
    const ProfileCutterSpec& p = profileCutterSpec(job);
    for (size_t i = 0; i < p.other_branches.size(); ++i) {
        const OtherBranch& o = p.other_branches[i];
        const std::string k = "other_branches[" + std::to_string(i) + "]";
        c.positive(k + ".radius_mm", o.radius_mm, 1, 2000, "mm");
        if (!(o.angle_deg >= 0.1 && o.angle_deg <= 179.9))
            c.add(k + ".angle_deg", messageC("other_branches[%zu].angle_deg = %.6g deg is outside "
                                             "[0.1, 179.9] deg (angle to the main axis)",
                                             i, o.angle_deg));
        c.range(k + ".eccentricity_mm", o.eccentricity_mm, -2000, 2000, "mm");
        c.range(k + ".position_mm", o.position_mm, -20000, 20000, "mm");
        c.range(k + ".phase_deg", o.phase_deg, -360, 360, "deg");
        const double fit = std::fabs(o.eccentricity_mm) + o.radius_mm;
        if (R > 0 && o.radius_mm > 0 && fit > R)
            c.add(k + ".radius_mm",
                  messageC("other_branches[%zu].radius_mm = %.6g mm does not fit: "
                           "|eccentricity_mm| + radius = %.6g mm must be <= main_pipe.radius_mm "
                           "= %.6g mm",
                           i, o.radius_mm, fit, R));
        // Axes must not be parallel to the cut branch's: the crossing would be undefined.
        const double aj = deg2rad(o.angle_deg), ph = deg2rad(o.phase_deg);
        const double cosAxes =
            std::sin(a) * std::cos(ph) * std::sin(aj) + std::cos(a) * std::cos(aj);
        const double between = rad2deg(std::acos(std::min(1.0, std::fabs(cosAxes))));
        if (std::isfinite(between) && between < 1.0)
            c.add(k + ".angle_deg", messageC("other_branches[%zu]: its axis is %.6g deg from the "
                                             "cut branch's axis; it must differ by >= 1 deg",
                                             i, between));
    }
    checkFields(c, profileCutterFields(), p);
    if (!p.branch_position_auto)
        c.range("profile_cutter.branch_position_mm", p.branch_position_mm, 0,
                job.main_pipe.length_mm, "mm");
    // The torch stands radially over the pipe: this machine cannot tilt it for a bevel.
    if (job.cut.bevel_deg != 0)
        c.add("cut.bevel_deg", messageC("cut.bevel_deg = %.6g deg: the 2-axis profile cutter "
                                        "cuts square only (0 deg)",
                                        job.cut.bevel_deg));
    return c.issues;
}

Outcome ProfileCutterModule::canOpen() const {
    return Outcome::refuse(
        messageC("the profile cutter's A and X steppers are driven by a pulse card, not by "
                 "CANopen drives: use devices.kind = \"simulated\""),
        "devices.kind");
}

MachinePlan ProfileCutterModule::plan(const Job& job, const std::string& jobText,
                                      const PlanOptions& /*options: plans in one go*/) const {
    MachinePlan out;
    auto data = std::make_shared<ProfileCutterPlanData>();
    data->cut = computeProfileCut(job);
    data->schedule = buildPulseSchedule(data->cut, profileCutterSpec(job), job.cut.speed_mm_s);
    out.data = data;
    const PulseSchedule& sch = data->schedule;
    out.summary =
        formatC("cut %s, %zu steps/rev, developed length %.2f mm at %.2f mm/s (%.2f s); largest "
                "pulse rates X %.0f Hz, A %.0f Hz (limit %.0f Hz)",
                toString(job.cut.target), data->cut.points.size(), sch.developed_length_mm,
                job.cut.speed_mm_s, sch.total_time_s, sch.max_x_rate_hz, sch.max_a_rate_hz,
                profileCutterSpec(job).max_pulse_rate_hz);
    if (data->cut.kerf_mm > 0)
        out.summary += formatC("; kerf %.2f mm compensated (torch %.2f mm off the edge)",
                               data->cut.kerf_mm, data->cut.kerf_mm / 2);
    if (!data->cut.kerf_problem.empty()) {
        out.outcome = Outcome::refuse(data->cut.kerf_problem, "process.override.kerf_mm");
        return out;
    }
    data->leads = computeProfileLeads(job, data->cut);
    if (!data->leads.problem.empty()) {
        out.outcome = Outcome::refuse(data->leads.problem, data->leads.problem_key);
        return out;
    }
    if (data->leads.used)
        out.summary += formatC("; lead-in %s %.2f mm, lead-out %s %.2f mm; pierce at Z %.2f mm "
                               "for %.2f s, cut at Z %.2f mm",
                               toString(data->leads.in.kind), data->leads.in.length_mm,
                               toString(data->leads.out.kind), data->leads.out.length_mm,
                               data->leads.pierce_height_mm, data->leads.pierce_delay_s,
                               data->leads.cut_height_mm);
    if (!sch.problem.empty()) {
        out.outcome = Outcome::refuse(messageC("not feasible: %s", sch.problem.c_str()));
        return out;
    }
    std::string travel = travelProblem(job, data->cut);
    if (travel.empty()) travel = leadTravelProblem(job, data->leads);
    if (!travel.empty()) {
        out.outcome = Outcome::refuse(messageC("not feasible: %s", travel.c_str()));
        return out;
    }
    try {
        out.program = buildProfileCutterProgram(job, data->leads, jobText);
    } catch (const std::invalid_argument& e) {
        out.outcome = Outcome::refuse(messageC("not feasible: %s", e.what()));
        return out;
    }
    out.outcome = Outcome::done();
    return out;
}

std::vector<ExportInfo> ProfileCutterModule::exports() const {
    return {{"path_csv", "cut path with stepper pulses (CSV)", "path.csv", true, false},
            {"gcode", "LinuxCNC G-code (X/A, inverse-time feed)", "cut.ngc", false, false},
            {"template_svg", "1:1 cutting template (SVG)", "template.svg", false, false},
            {"template_pdf", "1:1 cutting template (PDF)", "template.pdf", false, true}};
}

std::string ProfileCutterModule::exportFile(const std::string& exportId, const Job& job,
                                            const MachinePlan& plan) const {
    return exportFileWith(exportId, job, plan, ExportSettings{});
}

std::string ProfileCutterModule::exportFileWith(const std::string& exportId, const Job& job,
                                                const MachinePlan& plan,
                                                const ExportSettings& settings) const {
    const auto* data = static_cast<const ProfileCutterPlanData*>(plan.data.get());
    if (exportId == "template_svg" || exportId == "template_pdf") {
        const std::optional<Paper> paper = paperByName(settings.paper);
        if (!paper) {
            std::string names;
            for (const std::string& n : paperNames())
                names += (names.empty() ? "" : ", ") + n;
            throw std::invalid_argument("paper " + json::quote(settings.paper) + " is not one of " +
                                        names);
        }
        const TemplateDrawing drawing = buildTemplate(job, jointExtrasOf(job));
        if (exportId == "template_pdf")
            return templatePdf(templatePages(drawing, *paper, job.name));
        if (paper->short_mm <= 0) return templateSvg(drawing);
        return templateSvg(tileTemplate(drawing, *paper, job.name));
    }
    if (!data) throw std::invalid_argument("the plan has no profile cut");
    if (exportId == "path_csv")
        return profilePathCsv(data->cut, data->schedule, data->leads, job.cut.speed_mm_s);
    if (exportId == "gcode") return profileGcode(job, data->cut, data->leads);
    throw std::invalid_argument("the profile cutter has no export " + json::quote(exportId));
}

json::Value ProfileCutterModule::runReport(const Job&, const MachinePlan&,
                                           const TrackingReport& report) const {
    return profileRunReportJson(report);
}

bool ProfileCutterModule::isMachineParameter(const std::string& key) const {
    return keyUnder(key, {"profile_cutter.steps_per_rev_a", "profile_cutter.pulses_per_step_a",
                          "profile_cutter.mm_per_pulse_x", "profile_cutter.max_pulse_rate_hz",
                          "profile_cutter.x_travel_mm", "robot", "controller", "plant"});
}

} // namespace cutcell
