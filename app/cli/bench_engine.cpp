// cutcell-cli bench: the motion engine's real-time figures (cycle jitter and overruns over a
// run of the default job at 1 ms; emergency-stop latency over many trials), what its thread
// was granted (SCHED_FIFO, memory lock), the host's own wake-up latency measured like
// cyclictest at the same period for the same time (with the engine's p99 as a ratio to it), and
// the work of one cycle for each motion source (joint spline, master axis, control law).
// Printed, never asserted.
#include "bench_engine.h"

#include "core/engine/host_latency.h"
#include "core/engine/motion_engine.h"
#include "core/machines/pipe_robot/pipe_robot_program.h"
#include "core/trajectory/cut_planner.h"
#include "devices/sim/follower_rig.h"
#include "devices/sim/simulated_drive.h"
#include "devices/sim/simulated_torch.h"
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

struct SimCell {
    std::vector<std::unique_ptr<SimulatedDrive>> drives;
    SimulatedTorch torch;
    EngineDevices devices;

    explicit SimCell(const Job& job) {
        for (int i = 0; i < kAxisCount; ++i) {
            SimulatedDriveConfig dc;
            dc.gains = job.controller[static_cast<size_t>(i)];
            dc.plant = job.plant[static_cast<size_t>(i)];
            dc.period_s = job.sim.period_s;
            drives.push_back(std::make_unique<SimulatedDrive>(dc));
            devices.axes[static_cast<size_t>(i)] = drives.back().get();
        }
        devices.torch = &torch;
    }
};

EngineConfig realTimeConfig(const Job& job, const RealtimeSettings& realtime) {
    EngineConfig c;
    c.realtime = realtime;
    c.period_s = job.sim.period_s;
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

void benchSources(const Job& job, const std::shared_ptr<const MotionProgram>& spline, bool quick,
                  json::Object& out) {
    const int cycles = quick ? 5000 : 30000;
    {
        SimCell cell(job);
        EngineConfig c = fastConfig(job.sim.period_s);
        c.spec = job.engine;
        c.spec.runs_dir.clear();
        MotionEngine engine(cell.devices, c);
        engine.load(spline);
        if (startRun(engine, 20000))
            out.emplace_back("cycle_us_p99_joint_spline", cycleWorkP99(engine, cycles));
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
    const CutPlan plan = planCut(job);
    if (!plan.reachable) return;
    const auto program = buildPipeRobotProgram(job, plan);
    benchSources(job, program, quick, out);
    const double timedS = quick ? 2 : 10;

    // 0. The host alone: cyclictest's measurement (clock_nanosleep to absolute deadlines) on a
    //    thread set up like the engine's, same period, same duration as the timing run below.
    const HostLatency host = measureHostWakeupLatency(job.sim.period_s, timedS, realtime);
    out.emplace_back("host_wakeup_samples", static_cast<double>(host.samples));
    out.emplace_back("host_wakeup_latency_us_p50", host.p50_us);
    out.emplace_back("host_wakeup_latency_us_p99", host.p99_us);
    out.emplace_back("host_wakeup_latency_us_max", host.max_us);

    // 1. Cycle timing: the default job cutting in real time, telemetry drained at 30 Hz.
    {
        SimCell cell(job);
        MotionEngine engine(cell.devices, realTimeConfig(job, realtime));
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
    {
        SimCell cell(job);
        MotionEngine engine(cell.devices, realTimeConfig(job, realtime));
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
