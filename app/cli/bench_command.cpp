// cutcell-cli bench: speed figures of the core (and of the engine once it exists). Printed,
// never asserted: shared machines make timed assertions flaky.
#include "cli_commands.h"
#ifdef CUTCELL_HAVE_DEVICES
#include "bench_can.h"
#include "bench_engine.h"
#include "realtime_options.h"
#endif

#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/machine_registry.h"
#include "core/machines/pipe_robot/pipe_robot.h"
#include "core/sim/cut_simulation.h"
#include "core/trajectory/cut_planner.h"

#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

namespace cutcell::cli {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

// Mean time of one IK solve over reachable poses made by FK of random in-limit joints.
double benchIk(const Job& job, int poses, int repeats) {
    const PipeRobot robot(job.dh);
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

int runBench(const BenchOptions& o) {
    const bool asJson = o.json;
    const bool quick = o.quick;
    Job job = defaultJob();
    const std::string& jobFile = o.job;
    int code = kOk;
    if (!jobFile.empty() && !loadJobArg(jobFile, job, &code)) return code;
    job.sim.period_s = 0.001;
#ifdef CUTCELL_HAVE_DEVICES
    const RealtimeSettings& realtime =
        o.rt; // --rt-priority, --rt-cpu, --rt-dma-latency, --no-mlock
#endif

    json::Object out;
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
    for (const MachineModule* m : machines())
        m->addBenchFigures(quick, out);
#ifdef CUTCELL_HAVE_DEVICES
    if (!o.no_engine) benchEngine(job, quick, realtime, out);
#endif

#ifdef CUTCELL_HAVE_DEVICES
    if (!o.no_can) benchCan(out, quick);
#endif
    const json::Value doc(std::move(out));
    if (asJson) {
        std::fputs(json::write(doc).c_str(), stdout);
    } else {
        for (const auto& [k, v] : doc.asObject())
            std::printf("%-28s %.6g\n", k.c_str(), v.asNumber());
    }
    return kOk;
}

} // namespace cutcell::cli
