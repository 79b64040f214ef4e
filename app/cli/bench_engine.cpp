// cutcell-cli bench: the motion engine's real-time figures (cycle jitter and overruns over a
// run of the job - the default job unless --job - at 1 ms on its machine's simulated cell;
// emergency-stop latency over many trials), what its thread was granted (SCHED_FIFO, memory lock),
// the host's own wake-up latency measured like cyclictest at the same period for the same time
// (with the engine's p99 as a ratio to it), and the work of one cycle for each motion source (joint
// spline, master axis, control law). Printed, never asserted.
#include "bench_engine.h"

#include "core/engine/host_latency.h"
#include "core/engine/motion_engine.h"
#include "core/machine/machine_registry.h"
#include "devices/machines/sim_rig_registry.h"
#include "devices/sim/follower_rig.h"
#include "devices/sim/slider_rig.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <random>
#include <thread>
#include <vector>

namespace cutcell::cli {
namespace {

using namespace std::chrono_literals;

// The job's machine's simulated cell for its program (null, said on stderr, when it has none).
std::unique_ptr<MachineSimRig> simulatedCell(const Job& job, const MotionProgram& program) {
    std::string error;
    auto rig = makeSimulatedRig(job, program, &error);
    if (!rig) std::fprintf(stderr, "bench: no simulated cell: %s\n", error.c_str());
    return rig;
}

EngineConfig realTimeConfig(const Job& job, const MachineSimRig& rig,
                            const RealtimeSettings& realtime) {
    EngineConfig c;
    rig.configure(c); // the machine's period, windows and gains
    c.realtime = realtime;
    c.clock = ClockMode::RealTime;
    c.spec = job.engine;
    c.spec.runs_dir.clear(); // no run log in the benchmark
    return c;
}

void drain(MotionEngine& engine) {
    TelemetrySample t;
    while (engine.popTelemetry(t)) {
    }
    EngineEvent e;
    while (engine.popEvent(e)) {
    }
}

bool waitFor(MotionEngine& engine, EngineState s, std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (engine.state() != s) {
        if (std::chrono::steady_clock::now() > end) return false;
        std::this_thread::sleep_for(200us);
        drain(engine);
    }
    return true;
}

double quantile(std::vector<double> v, double p) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const auto k = static_cast<size_t>(std::ceil(p * static_cast<double>(v.size()))) - 1;
    return v[std::min(k, v.size() - 1)];
}

// The engine's own work per cycle (runCycles(1) timed on this thread, fast clock; telemetry
// and events drained between timed cycles, untimed): the 99th percentile in us.
double cycleWorkP99(MotionEngine& engine, int cycles) {
    std::vector<double> us;
    us.reserve(static_cast<size_t>(cycles));
    for (int k = 0; k < cycles; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        engine.runCycles(1, static_cast<EngineState>(255));
        const auto t1 = std::chrono::steady_clock::now();
        us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
        if (k % 30 == 0) drain(engine);
    }
    return quantile(us, 0.99);
}

EngineConfig fastConfig(double period_s) {
    EngineConfig c;
    c.period_s = period_s;
    c.clock = ClockMode::AsFastAsPossible;
    c.spec.runs_dir.clear();
    return c;
}

// Starts the program and runs until its source is moving (the figures are of the run itself).
bool startRun(MotionEngine& engine, int maxCycles) {
    auto until = [&](EngineState s) {
        engine.runCycles(1, static_cast<EngineState>(255)); // takes the pending command
        for (int k = 0; k < maxCycles && engine.state() != s; ++k) {
            engine.runCycles(1, static_cast<EngineState>(255));
            if (k % 30 == 0) drain(engine);
        }
    };
    engine.enable();
    until(EngineState::Ready);
    engine.home();
    until(EngineState::Ready);
    engine.start();
    engine.runCycles(1, static_cast<EngineState>(255));
    return engine.state() == EngineState::Running;
}

// The job's own program (its source's figure: the joint spline for the default job), then the
// other two motion sources on their small rigs.
void benchSources(const Job& job, const std::shared_ptr<const MotionProgram>& program, bool quick,
                  json::Object& out) {
    const int cycles = quick ? 5000 : 30000;
    if (auto rig = simulatedCell(job, *program)) {
        EngineConfig c = fastConfig(job.sim.period_s);
        rig->configure(c);
        c.clock = ClockMode::AsFastAsPossible;
        c.spec = job.engine;
        c.spec.runs_dir.clear();
        MotionEngine engine(rig->devices(), c);
        engine.load(program);
        std::string key = std::string("cycle_us_p99_") + toString(program->source_kind);
        std::replace(key.begin(), key.end(), ' ', '_'); // cycle_us_p99_joint_spline
        if (startRun(engine, 20000)) out.emplace_back(key, cycleWorkP99(engine, cycles));
    }
    {
        FollowerRigOptions o;
        o.line.speed_mm_s = 200;
        o.line.speed_amplitude = 0.1;
        o.line.noise_mm = 0.005;
        o.follower.first_sync = 300;
        o.follower.start_distance = 60;
        o.follower.sync_span = 200;
        o.follower.cut_length = 500;
        o.follower.cut_count = 1000;
        o.follower.return_s = 0.5;
        FollowerRig rig(o);
        EngineConfig c = fastConfig(0.001);
        rig.configure(c);
        MotionEngine engine(rig.devices(), c);
        engine.load(rig.program());
        if (startRun(engine, 2000))
            out.emplace_back("cycle_us_p99_master_axis", cycleWorkP99(engine, cycles));
    }
    {
        SliderRigOptions o;
        o.law.stroke_count = 100000;
        SliderRig rig(o);
        EngineConfig c = fastConfig(0.001);
        rig.configure(c);
        MotionEngine engine(rig.devices(), c);
        engine.load(rig.program());
        if (startRun(engine, 2000))
            out.emplace_back("cycle_us_p99_control_law", cycleWorkP99(engine, cycles));
    }
}

} // namespace

void benchEngine(const Job& job, bool quick, const RealtimeSettings& realtime, json::Object& out) {
    const MachinePlan plan = machineFor(job).plan(job);
    if (!plan.ok() || !plan.program) {
        std::fprintf(stderr, "bench: the job does not plan: %s\n", plan.outcome.message.c_str());
        return;
    }
    const std::shared_ptr<const MotionProgram> program = plan.program;
    benchSources(job, program, quick, out);
    const double timedS = quick ? 2 : 10;

    // 0. The host alone: cyclictest's measurement (clock_nanosleep to absolute deadlines) on a
    //    thread set up like the engine's, same period, same duration as the timing run below.
    const HostLatency host = measureHostWakeupLatency(job.sim.period_s, timedS, realtime);
    out.emplace_back("host_wakeup_samples", static_cast<double>(host.samples));
    out.emplace_back("host_wakeup_latency_us_p50", host.p50_us);
    out.emplace_back("host_wakeup_latency_us_p99", host.p99_us);
    out.emplace_back("host_wakeup_latency_us_max", host.max_us);

    // 1. Cycle timing: the job cutting in real time, telemetry drained at 30 Hz.
    if (auto rig = simulatedCell(job, *program)) {
        MotionEngine engine(rig->devices(), realTimeConfig(job, *rig, realtime));
        engine.load(program);
        engine.enable();
        engine.home();
        engine.start();
        engine.startThread();
        const auto end = std::chrono::steady_clock::now() +
                         std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>(timedS));
        while (std::chrono::steady_clock::now() < end) {
            std::this_thread::sleep_for(33ms);
            drain(engine);
        }
        engine.stopThread();
        const CycleStats s = engine.cycleStats();
        out.emplace_back("cycle_period_us", s.period_s * 1e6);
        out.emplace_back("cycle_count", static_cast<double>(s.cycles));
        out.emplace_back("cycle_jitter_us_p50", s.jitter_us_p50);
        out.emplace_back("cycle_jitter_us_p99", s.jitter_us_p99);
        out.emplace_back("cycle_jitter_us_max", s.jitter_us_max);
        out.emplace_back("cycle_overruns", static_cast<double>(s.overruns));
        out.emplace_back("cycle_missed_deadlines", static_cast<double>(s.missed_deadlines));
        out.emplace_back("cycle_work_us_max", s.work_us_max);
        out.emplace_back("telemetry_dropped", static_cast<double>(s.telemetry_dropped));
        // What the engine thread was granted (1 = yes, 0 = no), and what it adds to the host.
        const RealtimeStatus rt = engine.realtimeStatus();
        out.emplace_back("rt_priority_granted", rt.rt_priority_granted ? 1 : 0);
        out.emplace_back("rt_priority", rt.priority);
        out.emplace_back("memory_locked", rt.memory_locked ? 1 : 0);
        if (realtime.cpu >= 0) out.emplace_back("cpu_pinned", rt.cpu_pinned ? 1 : 0);
        if (realtime.cpu_dma_latency)
            out.emplace_back("cpu_dma_latency_held", rt.dma_latency_held ? 1 : 0);
        out.emplace_back("engine_jitter_to_host_ratio",
                         host.p99_us > 0 ? s.jitter_us_p99 / host.p99_us : 0.0);
    }

    // 2. Emergency-stop latency: request at a random phase of the cycle, measured by the
    //    engine from the request to "all drives read back disabled and torch off".
    if (auto rig = simulatedCell(job, *program)) {
        MotionEngine engine(rig->devices(), realTimeConfig(job, *rig, realtime));
        engine.load(program);
        engine.enable();
        engine.startThread();
        std::mt19937 rng(11);
        std::uniform_int_distribution<int> phaseUs(0, 1500);
        std::vector<double> latencies;
        const int trials = quick ? 100 : 1000;
        for (int k = 0; k < trials; ++k) {
            if (!waitFor(engine, EngineState::Ready, 2000ms)) break;
            std::this_thread::sleep_for(std::chrono::microseconds(phaseUs(rng)));
            const std::uint64_t before = engine.cycleStats().estops_measured;
            engine.emergencyStop();
            const auto end = std::chrono::steady_clock::now() + 2s;
            while (engine.cycleStats().estops_measured == before &&
                   std::chrono::steady_clock::now() < end)
                std::this_thread::sleep_for(100us);
            const CycleStats s = engine.cycleStats();
            if (s.estops_measured == before) break;
            latencies.push_back(s.last_estop_latency_us);
            engine.releaseEmergencyStop();
            engine.reset();
            if (!waitFor(engine, EngineState::Idle, 2000ms)) break;
            engine.enable();
        }
        engine.stopThread();
        out.emplace_back("estop_trials", static_cast<double>(latencies.size()));
        out.emplace_back("estop_latency_us_p50", quantile(latencies, 0.50));
        out.emplace_back("estop_latency_us_p99", quantile(latencies, 0.99));
        out.emplace_back("estop_latency_us_max", quantile(latencies, 1.0));
    }
}

} // namespace cutcell::cli
