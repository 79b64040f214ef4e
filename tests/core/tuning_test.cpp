// SIMC tuning (core/control/simc_tuning.h) by its properties: the tuned PidFilter on the joint
// plant it was tuned for, simulated at the control period (the plant integrated independently by
// a fine RK4), is stable, its set-point step response has the overshoot and settling of SIMC's
// tight tuning, and the sampled loop's gain margin (from its frequency response) is near the
// GM ~ 3 Skogestad gives for tau_c = theta; the margin agrees with where the simulated loop goes
// unstable. Then the pipe robot's tuning of its six axes (pipe_robot_tuning.h).
#include "core/control/pid_filter.h"
#include "core/control/simc_tuning.h"
#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/machines/pipe_robot/cut_simulation.h"
#include "core/machines/pipe_robot/pipe_robot_mechanics.h"
#include "core/machines/pipe_robot/pipe_robot_tuning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

using namespace cutcell;

namespace {

struct StepResponse {
    double overshoot = 0;   // (peak - 1), the step is 1
    double settling_s = -1; // last time outside +-2 %, -1: never settled
    double final_error = 0; // |1 - q| at the end
    double peak_abs = 0;    // of q over the whole run (divergence shows here)
};

// J q'' + b q' = u, u from the PidFilter at the period T (held), r = 1 from t = 0; RK4 with
// `substeps` steps per period. gainScale multiplies Kp, Ki, Kd.
StepResponse stepResponse(double J, double b, PidGains g, double T, double duration,
                          double gainScale = 1, int substeps = 20) {
    g.kp *= gainScale;
    g.ki *= gainScale;
    g.kd *= gainScale;
    PidFilter pid(g, T);
    double q = 0, v = 0;
    StepResponse r;
    double peak = 0;
    const long steps = static_cast<long>(std::ceil(duration / T));
    for (long k = 0; k <= steps; ++k) {
        const double t = static_cast<double>(k) * T;
        peak = std::max(peak, q);
        r.peak_abs = std::max(r.peak_abs, std::fabs(q));
        if (std::fabs(q - 1) > 0.02) r.settling_s = t;
        if (!std::isfinite(q) || r.peak_abs > 1e6) break;
        const double u = pid.step(1 - q);
        const double h = T / substeps;
        const auto acc = [&](double vel) { return (u - b * vel) / J; };
        for (int s = 0; s < substeps; ++s) {
            const double k1q = v, k1v = acc(v);
            const double k2q = v + h / 2 * k1v, k2v = acc(v + h / 2 * k1v);
            const double k3q = v + h / 2 * k2v, k3v = acc(v + h / 2 * k2v);
            const double k4q = v + h * k3v, k4v = acc(v + h * k3v);
            q += h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
            v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        }
    }
    r.overshoot = peak - 1;
    r.final_error = std::fabs(1 - q);
    return r;
}

struct Case {
    double J, b, T, tau_f;
};

// Joints from a light wrist to a loaded chuck, friction from none to heavy, periods of 0.25 to
// 4 ms: the default job's range and well beyond it, plus random draws (fixed seed).
std::vector<Case> cases() {
    std::vector<Case> c = {
        {0.1, 0.5, 0.001, 0.002},  {0.3, 1.0, 0.001, 0.002},  {0.02, 0.1, 0.001, 0.002},
        {0.5, 0.0, 0.001, 0.002},  {2.0, 50.0, 0.001, 0.002}, {0.004, 0.2, 0.00025, 0.0005},
        {1.5, 0.05, 0.004, 0.004}, {0.05, 5.0, 0.002, 0.001},
    };
    std::mt19937 rng(20031);
    std::uniform_real_distribution<double> logJ(std::log(1e-3), std::log(10.0));
    std::uniform_real_distribution<double> logTau1(std::log(1e-3), std::log(100.0));
    std::uniform_real_distribution<double> logT(std::log(2.5e-4), std::log(4e-3));
    std::uniform_real_distribution<double> filter(0.5, 3.0);
    for (int i = 0; i < 24; ++i) {
        const double J = std::exp(logJ(rng)), T = std::exp(logT(rng));
        c.push_back({J, J / std::exp(logTau1(rng)), T, filter(rng) * T});
    }
    return c;
}

std::string describe(const Case& c, const SimcTuning& t) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "J %.4g b %.4g T %.4g tau_f %.4g: %s, Kp %.6g Ki %.6g Kd %.6g",
                  c.J, c.b, c.T, c.tau_f, toString(t.rule), t.gains.kp, t.gains.ki, t.gains.kd);
    return buf;
}

} // namespace

TEST(Simc, RulesAsWritten) {
    SimcOptions o;
    o.period_s = 0.001;
    o.tau_f_s = 0.002;
    // theta = T/2 + tau_f; tau_c = theta unless given.
    const SimcTuning lag = simcTune(0.1, 0.5, o);
    EXPECT_DOUBLE_EQ(lag.theta_s, 0.0025);
    EXPECT_DOUBLE_EQ(lag.tau_c_s, lag.theta_s);
    EXPECT_EQ(lag.rule, SimcRule::IntegratingWithLag);
    const double c = lag.tau_c_s + lag.theta_s;
    EXPECT_DOUBLE_EQ(lag.kc, 0.5 / c);        // 1 / (k' (tau_c + theta)), k' = 1/b
    EXPECT_DOUBLE_EQ(lag.tau_i_s, 4 * c);     // 4 (tau_c + theta)
    EXPECT_DOUBLE_EQ(lag.tau_d_s, 0.1 / 0.5); // tau1 = J/b
    EXPECT_EQ(lag.gains.tau_f, o.tau_f_s);
    // The parallel gains are the series controller: compare the two at a few s.
    for (const std::complex<double> s : {std::complex<double>(0, 3.0), {0, 300.0}, {2.0, 40.0}}) {
        const auto series = lag.kc * (1.0 + 1.0 / (lag.tau_i_s * s)) * (1.0 + lag.tau_d_s * s);
        const auto parallel = lag.gains.kp + lag.gains.ki / s + lag.gains.kd * s;
        EXPECT_NEAR(std::abs(series - parallel), 0, 1e-9 * std::abs(series));
    }
    // A given tau_c.
    o.tau_c_s = 0.01;
    EXPECT_DOUBLE_EQ(simcTune(0.1, 0.5, o).tau_c_s, 0.01);
    o.tau_c_s = 0;

    // Without friction: the double integrator, Kc = 1/(4 k'' (tau_c + theta)^2), k'' = 1/J.
    const SimcTuning di = simcTune(0.1, 0, o);
    EXPECT_EQ(di.rule, SimcRule::DoubleIntegrating);
    EXPECT_DOUBLE_EQ(di.kc, 0.1 / (4 * c * c));
    EXPECT_DOUBLE_EQ(di.tau_i_s, 4 * c);
    EXPECT_DOUBLE_EQ(di.tau_d_s, 4 * c);
    // The two rules meet where the lag is 4 (tau_c + theta): same parallel gains.
    o.rule = SimcRule::IntegratingWithLag;
    const SimcTuning meet = simcTune(0.1, 0.1 / (4 * c), o);
    EXPECT_NEAR(meet.gains.kp, di.gains.kp, 1e-9 * di.gains.kp);
    EXPECT_NEAR(meet.gains.ki, di.gains.ki, 1e-9 * di.gains.ki);
    EXPECT_NEAR(meet.gains.kd, di.gains.kd, 1e-9 * di.gains.kd);
    EXPECT_THROW(simcTune(0.1, 0, o), std::invalid_argument); // lag rule without a lag
    EXPECT_THROW(simcTune(0, 1, {}), std::invalid_argument);
    EXPECT_THROW(simcTune(1, -1, {}), std::invalid_argument);
}

// The property: every tuned loop is stable, answers a step as SIMC's tight tuning does, and has
// the gain margin it was tuned for.
TEST(Simc, TunedLoopsAreStableWithSimcStepResponseAndMargins) {
    double gmMin = 1e9, gmMax = 0, osMax = 0, pmMin = 1e9;
    for (const Case& c : cases()) {
        SimcOptions o;
        o.period_s = c.T;
        o.tau_f_s = c.tau_f;
        const SimcTuning t = simcTune(c.J, c.b, o);
        const std::string what = describe(c, t);
        const double closed = t.tau_c_s + t.theta_s;

        const LoopMargins m = sampledLoopMargins(c.J, c.b, t.gains, c.T);
        EXPECT_TRUE(m.stable) << what << " spectral radius " << m.spectral_radius;
        // SIMC's tight tuning aims at GM ~ 3 for a pure delay. Here theta is half a period of
        // hold and the whole filter lag tau_f, and a lag costs less phase than the delay it is
        // counted as: the margin grows with tau_f/T (about 7.4 at T = 1 ms, tau_f = 2 ms, the
        // default job's drives) and falls towards 2 where the period dominates (measured over
        // these plants: 1.94 .. 11.7, PM >= 29 deg).
        EXPECT_GE(m.gain_margin, 1.8) << what;
        EXPECT_LE(m.gain_margin, 15.0) << what; // not needlessly sluggish either
        EXPECT_GE(m.phase_margin_deg, 27.0) << what;
        gmMin = std::min(gmMin, m.gain_margin);
        gmMax = std::max(gmMax, m.gain_margin);
        pmMin = std::min(pmMin, m.phase_margin_deg);

        // The step: integrating processes under PI(D) overshoot a set-point step (the integral
        // must unwind); SIMC's tight tuning keeps it below about half.
        const double settleBound =
            40 * closed + 3 * (t.rule == SimcRule::IntegratingWithLag ? c.J / c.b : 0.0);
        const StepResponse r = stepResponse(c.J, c.b, t.gains, c.T, 2 * settleBound + 0.1);
        EXPECT_LT(r.overshoot, 0.6) << what;
        EXPECT_GT(r.overshoot, 0.0) << what; // tight, not sluggish
        EXPECT_GE(r.settling_s, 0) << what;
        EXPECT_LT(r.settling_s, settleBound) << what << " settled at " << r.settling_s;
        EXPECT_LT(r.final_error, 0.005) << what;
        osMax = std::max(osMax, r.overshoot);

        // The margin is where the simulated loop (the real PidFilter) goes unstable.
        if (std::isfinite(m.gain_margin)) {
            const double horizon = 400 * closed;
            const StepResponse below =
                stepResponse(c.J, c.b, t.gains, c.T, horizon, 0.9 * m.gain_margin);
            const StepResponse above =
                stepResponse(c.J, c.b, t.gains, c.T, horizon, 1.1 * m.gain_margin);
            EXPECT_LT(below.final_error, 0.05) << what << " at 0.9 GM";
            EXPECT_GT(above.peak_abs, 10) << what << " at 1.1 GM";
        }
    }
    std::printf("SIMC over %zu plants: GM %.2f .. %.2f, PM >= %.1f deg, overshoot <= %.0f %%\n",
                cases().size(), gmMin, gmMax, pmMin, 100 * osMax);
}

TEST(Simc, LargerTauCIsSlowerAndMoreRobust) {
    SimcOptions o;
    const SimcTuning tight = simcTune(0.3, 1.0, o);
    o.tau_c_s = 4 * tight.theta_s;
    const SimcTuning smooth = simcTune(0.3, 1.0, o);
    EXPECT_LT(smooth.gains.kp, tight.gains.kp);
    EXPECT_LT(smooth.gains.ki, tight.gains.ki);
    EXPECT_GT(sampledLoopMargins(0.3, 1.0, smooth.gains, o.period_s).gain_margin,
              sampledLoopMargins(0.3, 1.0, tight.gains, o.period_s).gain_margin);
}

TEST(PipeRobotTuning, RigidBodyAxesAtTheCutsMeanConfiguration) {
    const Job job = defaultJob();
    const PipeRobotSpec& spec = pipeRobotSpec(job);
    ASSERT_EQ(spec.plant_model, PlantModel::RigidBody);
    const PipeRobotTuning t = tunePipeRobot(job);
    ASSERT_TRUE(t.outcome.ok()) << t.outcome.message;

    // q_mean is the mean of the planned trajectory.
    const CutPlan plan = planCut(job);
    JointVector lo = plan.spline.knot(0), hi = lo;
    for (size_t k = 0; k < plan.spline.knotCount(); ++k) {
        lo = lo.cwiseMin(plan.spline.knot(k));
        hi = hi.cwiseMax(plan.spline.knot(k));
    }
    for (int i = 0; i < kAxisCount; ++i) {
        EXPECT_GE(t.q_mean[i], lo[i] - 1e-9) << i;
        EXPECT_LE(t.q_mean[i], hi[i] + 1e-9) << i;
    }
    // J: the chuck's inertia, the arm's M_ii there (rotor included), b: the drives'.
    EXPECT_DOUBLE_EQ(t.axes[0].simc.inertia_kg_m2, pipeRobotChuckInertia(job));
    ChainDynamics::Vector q = ChainDynamics::Vector::Zero();
    for (int i = 0; i < kArmJointCount; ++i)
        q[i] = t.q_mean[i + 1];
    ChainDynamics::Matrix M;
    const ChainDynamics arm = pipeRobotArmDynamics(spec);
    arm.massMatrix(q, M);
    for (int i = 0; i < kArmJointCount; ++i) {
        const auto& a = t.axes[static_cast<size_t>(i + 1)].simc;
        EXPECT_DOUBLE_EQ(a.inertia_kg_m2, M(i, i)) << i;
        EXPECT_GT(a.inertia_kg_m2, arm.joint(i).rotor_inertia_kg_m2) << i;
    }
    for (size_t i = 0; i < kAxisCount; ++i) {
        const PipeRobotAxisTuning& a = t.axes[i];
        EXPECT_EQ(a.simc.viscous_nm_s_per_rad, spec.drives[i].viscous_nm_s_per_rad) << i;
        EXPECT_EQ(t.gains[i].tau_f, spec.controller[i].tau_f) << i;
        EXPECT_NEAR(a.simc.theta_s, job.sim.period_s / 2 + spec.controller[i].tau_f, 1e-15);
        // The rounded gains are the computed ones to the file's decimals.
        EXPECT_NEAR(t.gains[i].kp, a.simc.gains.kp, 0.005 + 1e-9) << i;
        EXPECT_NEAR(t.gains[i].ki, a.simc.gains.ki, 0.05 + 1e-9) << i;
        EXPECT_NEAR(t.gains[i].kd, a.simc.gains.kd, 0.0005 + 1e-9) << i;
        EXPECT_TRUE(a.margins.stable) << a.axis;
        EXPECT_GE(a.margins.gain_margin, 2.0) << a.axis;
    }
    const std::string text = pipeRobotTuningText(t);
    EXPECT_NE(text.find("theta3"), std::string::npos) << text;
    std::fputs(text.c_str(), stdout);
}

TEST(PipeRobotTuning, LinearPlantUsesThePlantRows) {
    Job job = defaultJob();
    PipeRobotSpec& spec = pipeRobotSpec(job);
    spec.plant_model = PlantModel::Linear;
    const PipeRobotTuning t = tunePipeRobot(job, 0.01);
    ASSERT_TRUE(t.outcome.ok());
    for (size_t i = 0; i < kAxisCount; ++i) {
        EXPECT_EQ(t.axes[i].simc.inertia_kg_m2, spec.plant[i].inertia_kg_m2);
        EXPECT_EQ(t.axes[i].simc.viscous_nm_s_per_rad, spec.plant[i].viscous_nm_s_per_rad);
        EXPECT_EQ(t.axes[i].simc.tau_c_s, 0.01);
    }
}

// The tuned gains run the default cut on the rigid-body plant: the module's hook writes them,
// and the offline simulation tracks the path with them.
TEST(PipeRobotTuning, ModuleHookWritesGainsThatTrackTheCut) {
    Job job = defaultJob();
    const MachineModule& module = machineFor(job);
    std::string text;
    ASSERT_TRUE(module.tuneControllers(job, {}, &text).ok());
    EXPECT_FALSE(text.empty());
    const PipeRobotTuning t = tunePipeRobot(defaultJob());
    for (size_t i = 0; i < kAxisCount; ++i)
        EXPECT_EQ(pipeRobotSpec(job).controller[i].kp, t.gains[i].kp);
    const CutPlan plan = planCut(job);
    const TrackingReport r = simulateCut(job, plan);
    for (int i = 0; i < kAxisCount; ++i)
        EXPECT_LT(r.maxAbs(i), 1.0) << "axis " << i << " (deg)"; // no loop runs away
    std::printf("tuned gains on the default cut: on-pipe max error %.4f %.4f %.4f mm, peak torque "
                "%.0f %% of the limit\n",
                r.on_pipe_max_abs_mm.x(), r.on_pipe_max_abs_mm.y(), r.on_pipe_max_abs_mm.z(),
                100 * r.max_torque_fraction);

    // Another machine's module has no tuning, and says so with the key machine.kind.
    const std::string sawFile = CUTCELL_SOURCE_DIR "/resources/jobs/flying_saw_job.json";
    Job saw = loadJobFile(sawFile);
    const Outcome no = machineFor(saw).tuneControllers(saw, {}, &text);
    EXPECT_TRUE(no.refused());
    EXPECT_EQ(no.key, "machine.kind");
    EXPECT_NE(no.message.find("no controller tuning"), std::string::npos) << no.message;
}
