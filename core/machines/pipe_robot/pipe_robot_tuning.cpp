#include "core/machines/pipe_robot/pipe_robot_tuning.h"

#include "core/common/c_format.h"
#include "core/job/drive_fields.h"
#include "core/job/job_io.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/machines/pipe_robot/pipe_robot_mechanics.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"

#include <cmath>

namespace cutcell {
namespace {

// Samples of the trajectory's time average (mid-points of equal intervals).
constexpr int kMeanSamples = 1000;

JointVector meanConfiguration(const CutPlan& plan) {
    JointVector sum = JointVector::Zero();
    const double duration = plan.spline.duration();
    for (int k = 0; k < kMeanSamples; ++k)
        sum += plan.spline.position((k + 0.5) / kMeanSamples * duration);
    return sum / kMeanSamples;
}

// The gains as the job file keeps them (the decimals of core/job/drive_fields.h); tau_f as is.
PidGains rounded(PidGains g) {
    for (const RowField<PidGains>& f : pidGainFields()) {
        double& v = f.number(g);
        if (&v == &g.tau_f) continue;
        const double scale = std::pow(10.0, f.decimals);
        v = std::round(v * scale) / scale;
    }
    return g;
}

} // namespace

PipeRobotTuning tunePipeRobot(const Job& job, double tau_c_s, const PlanOptions& options) {
    const PipeRobotSpec& spec = pipeRobotSpec(job);
    PipeRobotTuning out;
    out.model = spec.plant_model;
    std::array<double, kAxisCount> inertia{}, viscous{};
    if (spec.plant_model == PlantModel::Linear) {
        for (size_t i = 0; i < kAxisCount; ++i) {
            inertia[i] = spec.plant[i].inertia_kg_m2;
            viscous[i] = spec.plant[i].viscous_nm_s_per_rad;
        }
    } else {
        const CutPlan plan = planCut(job, options);
        if (plan.cancelled) {
            out.outcome = Outcome::cancel();
            return out;
        }
        if (!plan.reachable || plan.spline.empty()) {
            out.outcome = Outcome::refuse(
                "the cut cannot be planned, and the rigid-body tuning needs its poses: " +
                (plan.problem.empty() ? std::string("no trajectory") : plan.problem));
            return out;
        }
        out.q_mean = meanConfiguration(plan);
        ChainDynamics::Vector q = ChainDynamics::Vector::Zero();
        for (int i = 0; i < kArmJointCount; ++i)
            q[i] = out.q_mean[i + 1];
        ChainDynamics::Matrix M;
        pipeRobotArmDynamics(spec).massMatrix(q, M);
        inertia[0] = pipeRobotChuckInertia(job);
        for (int i = 0; i < kArmJointCount; ++i)
            inertia[static_cast<size_t>(i + 1)] = M(i, i);
        for (size_t i = 0; i < kAxisCount; ++i)
            viscous[i] = spec.drives[i].viscous_nm_s_per_rad;
    }
    const std::vector<AxisInfo> names = PipeRobotModule().axes(job);
    for (size_t i = 0; i < kAxisCount; ++i) {
        SimcOptions o;
        o.period_s = job.sim.period_s;
        o.tau_f_s = spec.controller[i].tau_f;
        o.tau_c_s = tau_c_s;
        PipeRobotAxisTuning& a = out.axes[i];
        a.axis = names[i].name;
        a.simc = simcTune(inertia[i], viscous[i], o);
        out.gains[i] = rounded(a.simc.gains);
        a.margins = sampledLoopMargins(inertia[i], viscous[i], out.gains[i], o.period_s);
    }
    return out;
}

std::string pipeRobotTuningText(const PipeRobotTuning& t) {
    std::string s =
        formatC("SIMC tuning (Skogestad 2003), %s plant%s\n",
                t.model == PlantModel::Linear ? "linear" : "rigid-body",
                t.model == PlantModel::Linear ? " (plant[])" : " at the cut's mean configuration");
    s += formatC("%-15s %10s %10s %8s %11s %12s %10s %8s %6s %7s\n", "axis", "J", "b", "theta",
                 "Kp", "Ki", "Kd", "tau_f", "GM", "PM");
    s += formatC("%-15s %10s %10s %8s %11s %12s %10s %8s %6s %7s\n", "", "kg m^2", "N m s/rad",
                 "ms", "N m/rad", "N m/(rad s)", "N m s/rad", "ms", "", "deg");
    for (size_t i = 0; i < kAxisCount; ++i) {
        const PipeRobotAxisTuning& a = t.axes[i];
        const PidGains& g = t.gains[i];
        s += formatC("%-15s %10.5f %10.4f %8.3f %11.2f %12.1f %10.3f %8.3f %6.2f %7.1f\n",
                     a.axis.c_str(), a.simc.inertia_kg_m2, a.simc.viscous_nm_s_per_rad,
                     a.simc.theta_s * 1e3, g.kp, g.ki, g.kd, g.tau_f * 1e3, a.margins.gain_margin,
                     a.margins.phase_margin_deg);
    }
    s += "theta = T/2 + tau_f; series PID Kc (1 + 1/(tau_I s)) (1 + tau_D s) -> Kp = Kc (1 + "
         "tau_D/tau_I), Ki = Kc/tau_I, Kd = Kc tau_D; GM, PM of the sampled loop\n";
    for (size_t i = 0; i < kAxisCount; ++i) {
        const SimcTuning& x = t.axes[i].simc;
        const std::string model = x.rule == SimcRule::IntegratingWithLag
                                      ? formatC("k' = 1/b, tau1 = J/b = %.1f ms",
                                                x.inertia_kg_m2 / x.viscous_nm_s_per_rad * 1e3)
                                      : formatC("k'' = 1/J = %.4g 1/(kg m^2)", 1 / x.inertia_kg_m2);
        s += formatC("%s: %s (%s), tau_c = %.3f ms, Kc = %.6g N m/rad, tau_I = %.3f ms, "
                     "tau_D = %.3f ms\n",
                     t.axes[i].axis.c_str(), toString(x.rule), model.c_str(), x.tau_c_s * 1e3, x.kc,
                     x.tau_i_s * 1e3, x.tau_d_s * 1e3);
    }
    return s;
}

// The module's hook (declared in pipe_robot_module.h, kept here beside the tuning).
Outcome PipeRobotModule::tuneControllers(Job& job, const TuneOptions& options,
                                         std::string* text) const {
    if (const std::vector<JobIssue> issues = validateJob(job); !issues.empty())
        return Outcome::refuse("the job is not valid: " + issues.front().message,
                               issues.front().key);
    const PipeRobotTuning t = tunePipeRobot(job, options.tau_c_s, options.plan);
    if (!t.outcome.ok()) return t.outcome;
    pipeRobotSpec(job).controller = t.gains;
    if (text) *text = pipeRobotTuningText(t);
    return Outcome::done();
}

} // namespace cutcell
