// The pipe robot's figures for `cutcell-cli bench` (the default job at 1 kHz): the time of one
// IK solve, planning plus the offline simulation of the cut against the time it simulates, the
// simulation alone on each plant model, and one forward dynamics of the arm.
#include "core/machines/pipe_robot/cut_simulation.h"
#include "core/machines/pipe_robot/pipe_robot_mechanics.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

namespace cutcell {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

// Mean time of one IK solve over reachable poses made by FK of random in-limit joints.
double benchIk(const Job& job, int poses, int repeats) {
    const PipeRobot robot(pipeRobotSpec(job).dh);
    std::mt19937 rng(7);
    std::vector<Pose> targets;
    targets.reserve(static_cast<size_t>(poses));
    for (int i = 0; i < poses; ++i) {
        ArmVector q;
        for (int j = 0; j < kArmJointCount; ++j) {
            std::uniform_real_distribution<double> d(robot.minRad(j + 1), robot.maxRad(j + 1));
            q[j] = d(rng);
        }
        targets.push_back(robot.forward(q));
    }
    volatile double sink = 0;
    const auto t0 = Clock::now();
    for (int r = 0; r < repeats; ++r)
        for (const Pose& p : targets)
            sink = sink + robot.solve(p).q[0];
    const auto t1 = Clock::now();
    return seconds(t0, t1) * 1e9 / (static_cast<double>(poses) * repeats);
}

// Simulated seconds per wall second of simulateCut alone (the plan made once) on a plant model,
// best of `runs`.
double benchSimulate(Job job, PlantModel model, int runs) {
    pipeRobotSpec(job).plant_model = model;
    const CutPlan plan = planCut(job);
    double best = 1e300, simulated = 0;
    for (int run = 0; run < runs; ++run) {
        const auto t0 = Clock::now();
        simulated = simulateCut(job, plan).simulated_s;
        best = std::min(best, seconds(t0, Clock::now()));
    }
    return simulated / best;
}

// Mean time (us) of one step of the rigid-body plant (a control period) with an integrator, the
// arm swinging under torques around its holding torques, best of five batches of 2 s.
double benchPlantStep(const Job& job, RigidIntegrator integrator) {
    const double T = 0.001;
    PipeRobotMechanics plant(job, T, 1, integrator);
    JointVector q0 = JointVector::Zero();
    q0.head(kAxisCount) << 0, 0.3, 0.5, -0.4, 0.6, 0;
    JointVector hold, torque, applied;
    plant.gravityTorques(q0, hold);
    constexpr int kSteps = 2000;
    double best = 1e300;
    for (int batch = 0; batch < 5; ++batch) {
        plant.setState(q0);
        const auto t0 = Clock::now();
        for (int k = 0; k < kSteps; ++k) {
            for (int i = 0; i < kAxisCount; ++i)
                torque[i] = hold[i] + 2.0 * std::sin(0.01 * k + i);
            plant.step(torque, applied);
        }
        best = std::min(best, seconds(t0, Clock::now()));
    }
    return best * 1e6 / kSteps;
}

// Mean time (us) of one ChainDynamics::forwardDynamics of the job's arm at random states, best
// of five batches.
double benchForwardDynamics(const Job& job, int repeats) {
    const ChainDynamics arm = pipeRobotArmDynamics(pipeRobotSpec(job));
    using V = ChainDynamics::Vector;
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-1, 1);
    constexpr int kStates = 256;
    std::vector<std::array<V, 3>> states(kStates);
    for (auto& s : states)
        for (V& v : s) {
            v.setZero();
            for (int i = 0; i < arm.size(); ++i)
                v[i] = 3 * u(rng);
        }
    V qdd;
    volatile double sink = 0;
    double best = 1e300;
    for (int batch = 0; batch < 5; ++batch) {
        const auto t0 = Clock::now();
        for (int r = 0; r < repeats; ++r)
            for (const auto& s : states) {
                arm.forwardDynamics(s[0], s[1], s[2], qdd);
                sink = sink + qdd[0];
            }
        best = std::min(best, seconds(t0, Clock::now()));
    }
    return best * 1e6 / (static_cast<double>(kStates) * repeats);
}

} // namespace

void PipeRobotModule::addBenchFigures(bool quick, json::Object& out) const {
    Job job = defaultJob();
    job.sim.period_s = 0.001;
    out.emplace_back("ik_ns_per_solve", benchIk(job, 2000, quick ? 20 : 200));

    // Plan + simulate the job at 1 kHz, best of five runs (the VM is noisy).
    double best = 1e300;
    TrackingReport report;
    for (int run = 0; run < (quick ? 1 : 5); ++run) {
        const auto t0 = Clock::now();
        const CutPlan plan = planCut(job);
        report = simulateCut(job, plan);
        best = std::min(best, seconds(t0, Clock::now()));
    }
    out.emplace_back("simulate_seconds", best);
    out.emplace_back("simulated_seconds", report.simulated_s);
    out.emplace_back("simulate_realtime_factor", report.simulated_s / best);
    // The simulation alone (plan made once) on each plant model, and the arm's dynamics.
    out.emplace_back("simulate_realtime_factor_rigid_body",
                     benchSimulate(job, PlantModel::RigidBody, quick ? 1 : 5));
    out.emplace_back("simulate_realtime_factor_linear",
                     benchSimulate(job, PlantModel::Linear, quick ? 1 : 5));
    out.emplace_back("forward_dynamics_us", benchForwardDynamics(job, quick ? 40 : 400));
    out.emplace_back("rigid_body_step_us_adams_nystrom",
                     benchPlantStep(job, RigidIntegrator::AdamsNystrom4));
    out.emplace_back("rigid_body_step_us_runge_kutta",
                     benchPlantStep(job, RigidIntegrator::RungeKutta4));
}

} // namespace cutcell
