// The pipe robot's figures for `cutcell-cli bench` (the default job at 1 kHz): the time of one
// IK solve, and planning plus the offline simulation of the cut against the time it simulates.
#include "core/machines/pipe_robot/cut_simulation.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"

#include <algorithm>
#include <chrono>
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
}

} // namespace cutcell
