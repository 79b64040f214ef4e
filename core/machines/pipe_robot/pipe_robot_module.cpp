#include "core/machines/pipe_robot/pipe_robot_module.h"
#include "core/machines/pipe_robot/robot_torch_height.h"

#include "core/machine/parameter_level.h"

#include "core/common/c_format.h"
#include "core/job/default_job.h"
#include "core/job/drive_fields.h"
#include "core/job/issue_checker.h"
#include "core/machine/pipe_joint_section.h"
#include "core/machines/pipe_robot/cut_simulation.h"
#include "core/machines/pipe_robot/pipe_robot_mechanics.h"
#include "core/machines/pipe_robot/pipe_robot_program.h"
#include "core/machines/pipe_robot/plan_csv.h"
#include "core/process/process_spec.h"
#include "core/sim/tracking_stats.h"

#include <cmath>

namespace cutcell {
namespace {

const CutKeys kCutKeys{};

// The robot's arrays have a row per axis.
constexpr const char* kRowsAre = "axis 0 = chuck, 1..5 = arm";

template <class Row>
void readAxisRows(SectionReader& parent, const std::string& leaf,
                  std::span<const RowField<Row>> table, std::array<Row, kAxisCount>& out) {
    readRows(requiredRows(parent, leaf, kAxisCount, kRowsAre), parent.key(leaf), table,
             std::span<Row>(out));
}

const char* const kAxisNames[kAxisCount] = {"chuck (theta0)", "theta1", "theta2",
                                            "theta3",         "theta4", "theta5"};

// The axes' names in reports (as in the axes and the engine's run log).
const std::array<std::string, kMaxAxes>& reportAxisNames() {
    static const std::array<std::string, kMaxAxes> names = [] {
        std::array<std::string, kMaxAxes> n;
        for (int i = 0; i < kAxisCount; ++i)
            n[static_cast<size_t>(i)] = kAxisNames[i];
        return n;
    }();
    return names;
}

} // namespace

std::vector<AxisInfo> PipeRobotModule::axes(const Job& job) const {
    std::vector<AxisInfo> out;
    for (int i = 0; i < kAxisCount; ++i) {
        const DhRow& r = pipeRobotSpec(job).dh[static_cast<size_t>(i)];
        out.push_back(
            {kAxisNames[i], AxisUnit::Rotary, r.min_deg, r.max_deg, CommandMode::Position});
    }
    return out;
}

Job PipeRobotModule::defaultJob() const {
    return cutcell::defaultJob();
}

void PipeRobotModule::readSection(const json::Value& section, Job& job) const {
    SectionReader m(section, "machine");
    m.get("kind");
    readPipeJoint(m, job, kCutKeys);
    PipeRobotSpec spec;
    spec.method = m.choice<CutMethod>(
        "method",
        {{"static_pipe", CutMethod::StaticPipe}, {"rotating_pipe", CutMethod::RotatingPipe}},
        CutMethod::RotatingPipe);
    spec.plant_model = m.choice<PlantModel>(
        "plant_model", {{"rigid_body", PlantModel::RigidBody}, {"linear", PlantModel::Linear}},
        PlantModel::RigidBody);
    spec.gravity_feedforward = m.boolean("gravity_feedforward", false);
    if (m.has("robot")) {
        SectionReader robot = m.child("robot");
        if (robot.has("dh")) readAxisRows(robot, "dh", dhRowFields(), spec.dh);
        if (robot.has("links"))
            readRows(requiredRows(robot, "links", kArmJointCount, "links 1..5 of the arm"),
                     robot.key("links"), armLinkFields(), std::span<ArmLinkRow>(spec.links));
        if (robot.has("drives")) readAxisRows(robot, "drives", driveTrainFields(), spec.drives);
        if (robot.has("chuck")) {
            SectionReader chuck = robot.child("chuck");
            spec.chuck.inertia_kg_m2 =
                chuck.number("inertia_kg_m2", "kg m^2", spec.chuck.inertia_kg_m2);
            spec.chuck.pipe_density_kg_m3 =
                chuck.number("pipe_density_kg_m3", "kg/m^3", spec.chuck.pipe_density_kg_m3);
            chuck.finish();
        }
        robot.finish();
    }
    readAxisRows(m, "controller", pidGainFields(), spec.controller);
    readAxisRows(m, "plant", jointPlantFields(), spec.plant);
    m.finish();
    job.machine_spec.set(std::move(spec));
}

json::Value PipeRobotModule::writeSection(const Job& job) const {
    const PipeRobotSpec& spec = pipeRobotSpec(job);
    json::Object s{{"kind", id()}};
    writePipeJoint(job, s, kCutKeys);
    s.emplace_back("method", toString(spec.method));
    s.emplace_back("plant_model", toString(spec.plant_model));
    s.emplace_back("gravity_feedforward", spec.gravity_feedforward);
    s.emplace_back(
        "robot", json::Object{{"dh", writeRows<DhRow>(dhRowFields(), spec.dh)},
                              {"links", writeRows<ArmLinkRow>(armLinkFields(), spec.links)},
                              {"drives", writeRows<DriveTrainRow>(driveTrainFields(), spec.drives)},
                              {"chuck", json::Object{{"inertia_kg_m2", spec.chuck.inertia_kg_m2},
                                                     {"pipe_density_kg_m3",
                                                      spec.chuck.pipe_density_kg_m3}}}});
    s.emplace_back("controller", writeRows<PidGains>(pidGainFields(), spec.controller));
    s.emplace_back("plant", writeRows<JointPlantParams>(jointPlantFields(), spec.plant));
    return s;
}

void PipeRobotModule::migrateSchema1(json::Object& section) const {
    // Schema 1 read the profile cutter's keys for every job; the robot never used them.
    std::erase_if(section, [](const auto& kv) {
        return kv.first == "other_branches" || kv.first == "profile_cutter";
    });
}

std::vector<JobIssue> PipeRobotModule::validate(const Job& job) const {
    const PipeRobotSpec& spec = pipeRobotSpec(job);
    IssueChecker c;
    checkPipeJoint(c, job, kCutKeys);
    checkRobotLeads(c, job);
    // The simulated pipe and arc of the torch height control (the chart's issues are the
    // process section's own).
    if (const RobotTorchHeightSetup t = robotTorchHeightSetup(job);
        t.problem_key.starts_with("process.torch_height"))
        c.add(t.problem_key, t.problem);
    for (int i = 0; i < kAxisCount; ++i) {
        const auto& d = spec.dh[static_cast<size_t>(i)];
        const std::string k = rowKey("robot.dh", static_cast<size_t>(i));
        checkRow(c, dhRowFields(), k, d);
        if (d.min_deg >= d.max_deg)
            c.add(k + ".min_deg", messageC("robot.dh[%d].min_deg = %.6g deg must be below "
                                           "robot.dh[%d].max_deg = %.6g deg",
                                           i, d.min_deg, i, d.max_deg));
        // Every axis homes to 0 deg (the program's reference): its range must hold it.
        else if (d.min_deg > 0)
            c.add(k + ".min_deg", messageC("robot.dh[%d].min_deg = %.6g deg: the axis's range "
                                           "must hold its reference 0 deg (at most 0 deg)",
                                           i, d.min_deg));
        else if (d.max_deg < 0)
            c.add(k + ".max_deg", messageC("robot.dh[%d].max_deg = %.6g deg: the axis's range "
                                           "must hold its reference 0 deg (at least 0 deg)",
                                           i, d.max_deg));
    }
    // The analytic IK is written for the seed's arm structure (alpha = 90, 0, 0, 90, 0).
    const double structure[kAxisCount] = {90, 90, 0, 0, 90, 0};
    for (int i = 1; i < kAxisCount; ++i) {
        const auto& d = spec.dh[static_cast<size_t>(i)];
        if (std::fabs(d.alpha_deg - structure[i]) > 1e-9)
            c.add("robot.dh[" + std::to_string(i) + "].alpha_deg",
                  messageC("robot.dh[%d].alpha_deg = %.6g deg: the pipe robot's inverse "
                           "kinematics needs %.6g deg",
                           i, d.alpha_deg, structure[i]));
    }
    // ... and for its offsets: these lengths are zero on the seed's arm.
    const struct {
        int row;
        const char* field;
        double value;
    } zeros[] = {{1, "a_mm", spec.dh[1].a_mm},
                 {2, "d_mm", spec.dh[2].d_mm},
                 {3, "d_mm", spec.dh[3].d_mm},
                 {4, "d_mm", spec.dh[4].d_mm},
                 {5, "a_mm", spec.dh[5].a_mm}};
    for (const auto& z : zeros)
        if (std::fabs(z.value) > 1e-9) {
            const std::string k = "robot.dh[" + std::to_string(z.row) + "]." + z.field;
            c.add(k, messageC("robot.dh[%d].%s = %.6g mm: the pipe robot's inverse kinematics "
                              "needs 0 mm",
                              z.row, z.field, z.value));
        }
    if (spec.dh[2].a_mm <= 0 || spec.dh[3].a_mm <= 0)
        c.add("robot.dh[2].a_mm",
              messageC("robot.dh[2].a_mm and robot.dh[3].a_mm must be > 0 mm (arm links)"));

    // The rigid-body plant's mechanics: ranges, and masses that make a mass matrix.
    checkRows(c, armLinkFields(), "robot.links", std::span<const ArmLinkRow>(spec.links));
    checkRows(c, driveTrainFields(), "robot.drives", std::span<const DriveTrainRow>(spec.drives));
    c.range("robot.chuck.inertia_kg_m2", spec.chuck.inertia_kg_m2, 0, 1e4, "kg m^2");
    c.range("robot.chuck.pipe_density_kg_m3", spec.chuck.pipe_density_kg_m3, 0, 25000, "kg/m^3");
    for (size_t i = 0; i < spec.links.size(); ++i)
        if (const std::string why = inertiaTensorProblem(spec.links[i]); !why.empty())
            c.add(rowKey("robot.links", i) + ".ixx_kg_cm2",
                  messageC("robot.links[%zu] (link %zu): %s", i, i + 1, why.c_str()));
    if (spec.plant_model == PlantModel::RigidBody && pipeRobotChuckInertia(job) <= 0)
        c.add("robot.chuck.inertia_kg_m2",
              messageC("robot.chuck.inertia_kg_m2 = %.6g kg m^2: the chuck axis has no inertia "
                       "(chuck, pipe and rotor sum to 0)",
                       spec.chuck.inertia_kg_m2));

    // The drives' physical ranges (core/job/drive_fields.h), axis by axis.
    for (int i = 0; i < kAxisCount; ++i) {
        const auto& g = spec.controller[static_cast<size_t>(i)];
        const std::string k = rowKey("controller", static_cast<size_t>(i));
        checkRow(c, pidGainFields(), k, g);
        checkRow(c, jointPlantFields(), rowKey("plant", static_cast<size_t>(i)),
                 spec.plant[static_cast<size_t>(i)]);
        // The filter time constant must be resolvable at the control period.
        if (g.tau_f > 0 && job.sim.period_s > 0 && g.tau_f < job.sim.period_s / 2)
            c.add(k + ".tau_f_s", messageC("controller[%d].tau_f_s = %.6g s must be >= half the "
                                           "control period (%.6g s)",
                                           i, g.tau_f, job.sim.period_s / 2));
    }
    return c.issues;
}

MachinePlan PipeRobotModule::plan(const Job& job, const std::string& jobText,
                                  const PlanOptions& options) const {
    MachinePlan out;
    auto cut = std::make_shared<CutPlan>(planCut(job, options));
    out.data = cut;
    if (cut->cancelled) {
        out.outcome = Outcome::cancel();
        return out;
    }
    out.summary =
        formatC("%s method, cut %s, %.2f mm at %.2f mm/s (%.2f s)", toString(cut->method),
                toString(job.cut.target), cut->length_mm, job.cut.speed_mm_s, cut->cut_time_s);
    if (cut->leads)
        out.summary +=
            formatC("; lead-in %s %.2f mm, lead-out %s %.2f mm, overlap %.2f mm; "
                    "pierce at %.2f mm for %.2f s, cut at %.2f mm",
                    toString(job.process.lead_in.kind), cut->lead_in_mm,
                    toString(job.process.lead_out.kind), cut->lead_out_mm, cut->overlap_mm,
                    cut->pierce_height_mm, cut->pierce_delay_s, cut->cut_height_mm);
    if (!cut->reachable) {
        out.outcome = Outcome::refuse(messageC("path not reachable (%s method): %s",
                                               toString(cut->method), cut->problem.c_str()),
                                      cut->problem_key);
        return out;
    }
    auto program = buildPipeRobotProgram(job, *cut, jobText);
    out.program = program;
    out.outcome = Outcome::done();
    return out;
}

Outcome PipeRobotModule::setVariant(Job& job, const std::string& variant) const {
    if (variant == "static_pipe")
        pipeRobotSpec(job).method = CutMethod::StaticPipe;
    else if (variant == "rotating_pipe")
        pipeRobotSpec(job).method = CutMethod::RotatingPipe;
    else
        return Outcome::refuse("--method = " + json::quote(variant) +
                                   " is not one of \"static_pipe\", \"rotating_pipe\"",
                               "machine.method");
    return Outcome::done();
}

std::vector<ExportInfo> PipeRobotModule::exports() const {
    return {
        {"path_csv", "cut path with torch poses (CSV)", "path.csv", true, false},
        {"joints_csv", "joint trajectory at the control period (CSV)", "joints.csv", true, false}};
}

std::string PipeRobotModule::exportFile(const std::string& exportId, const Job& job,
                                        const MachinePlan& plan) const {
    const CutPlan* cut = static_cast<const CutPlan*>(plan.data.get());
    if (!cut || !plan.ok()) throw std::invalid_argument("the plan has no reachable cut");
    if (exportId == "path_csv") return pathCsv(*cut);
    if (exportId == "joints_csv") return jointsCsv(*cut, job.sim.period_s);
    throw std::invalid_argument("the pipe robot has no export " + json::quote(exportId));
}

Outcome PipeRobotModule::offlineReport(const Job& job, const MachinePlan& plan, std::string* json,
                                       std::string* text) const {
    const CutPlan* cut = static_cast<const CutPlan*>(plan.data.get());
    if (!cut || !plan.ok()) return Outcome::refuse(plan.outcome.message);
    const TrackingReport report = simulateCut(job, *cut);
    *json = json::write(reportToJson(report, &reportAxisNames()));
    std::string t = formatC("%s method, %.1f s simulated at %.4f s\n", report.method.c_str(),
                            report.simulated_s, job.sim.period_s);
    t += formatC("%-16s %14s %14s\n", "axis", "max |e| (deg)", "rms (deg)");
    for (int i = 0; i < kAxisCount; ++i)
        t += formatC("%-16s %14.6f %14.6f\n",
                     i == 0 ? "0 chuck" : (std::to_string(i) + " arm").c_str(),
                     report.joints[static_cast<size_t>(i)].max_abs,
                     report.joints[static_cast<size_t>(i)].rms);
    t += formatC("tip error (mm), base frame: x %.6f  y %.6f  z %.6f\n",
                 report.cartesian_max_abs_mm.x(), report.cartesian_max_abs_mm.y(),
                 report.cartesian_max_abs_mm.z());
    *text = t;
    return Outcome::done();
}

json::Value PipeRobotModule::runReport(const Job& job, const MachinePlan& plan,
                                       const TrackingReport& report) const {
    TrackingReport r = report;
    r.method = toString(pipeRobotSpec(job).method);
    if (const CutPlan* cut = static_cast<const CutPlan*>(plan.data.get()))
        r.max_direction_deviation_deg = cut->max_deviation_deg;
    return reportToJson(r, &reportAxisNames());
}

bool PipeRobotModule::isMachineParameter(const std::string& key) const {
    return keyUnder(key, {"robot", "controller", "plant", "plant_model", "gravity_feedforward"});
}

} // namespace cutcell
