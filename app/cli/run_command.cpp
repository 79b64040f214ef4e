// cutcell-cli run: executes a job through the motion engine with simulated drives and torch
// (load -> enable -> home -> start -> completed), writes the run log and prints the report.
#include "cli_commands.h"

#include "core/engine/motion_engine.h"
#include "core/engine/run_log.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machines/pipe_robot_program.h"
#include "core/trajectory/cut_planner.h"
#include "devices/process/safe_shutdown.h"
#include "devices/sim/simulated_drive.h"
#include "devices/sim/simulated_torch.h"

#include "can_devices.h"
#include "realtime_options.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <thread>
#include <vector>

namespace cutcell::cli {

namespace {

void printEvents(MotionEngine& engine, bool quiet) {
    EngineEvent e;
    while (engine.popEvent(e))
        if (!quiet || e.severity != Severity::Info)
            std::fprintf(stderr, "%s\n", RunLog::formatEvent(e).c_str());
}

bool latched(EngineState s) {
    return s == EngineState::Fault || s == EngineState::EmergencyStop;
}

// Runs the engine (on this thread, or waits for its thread) until it reaches `target`, gives
// up on a fault or after budget_s of engine time; telemetry is drained as a GUI would.
bool runUntil(MotionEngine& engine, bool realtime, EngineState target, double budget_s,
              bool quiet) {
    const double period = engine.cycleStats().period_s;
    const auto chunk = static_cast<std::uint64_t>(0.033 / period) + 1; // a 30 Hz drain
    const auto t0 = std::chrono::steady_clock::now();
    const std::uint64_t c0 = engine.cycleStats().cycles;
    bool first = true;
    for (;;) {
        if (realtime) {
            std::this_thread::sleep_for(std::chrono::milliseconds(33));
        } else {
            // The first cycle takes the pending command even if the state already equals target.
            if (first) engine.runCycles(1, target);
            engine.runCycles(chunk, target);
        }
        first = false;
        TelemetrySample t;
        while (engine.popTelemetry(t)) {
        }
        printEvents(engine, quiet);
        if (!realtime) engine.flushRunLog();               // the thread mode has its own logger
        if (SafeShutdown::requestedSignal()) return false; // the safe stop has run: end
        const EngineState s = engine.state();
        if (s == target) return true;
        if (latched(s)) return false;
        const double elapsed =
            realtime ? std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()
                     : static_cast<double>(engine.cycleStats().cycles - c0) * period;
        if (elapsed > budget_s) return false;
    }
}

} // namespace

int runRun(const RunOptions& o) {
    Job job;
    std::string text;
    try {
        text = readTextFile(o.job);
        job = parseJob(text);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "invalid job: %s\n", e.what());
        return std::filesystem::exists(o.job) ? kInvalidJob : kFailure; // 1: cannot be read
    }
    if (job.machine == "profile_cutter_2axis") return runProfileRun(job, text, o);
    bool realtime = o.realtime;
    const bool quiet = o.quiet;
    if (!o.runs.empty()) job.engine.runs_dir = o.runs;
    RealtimeSettings rtSettings = o.rt; // the engine thread's set-up (with --realtime or CANopen)

    const CutPlan plan = planCut(job);
    if (!plan.reachable) {
        std::fprintf(stderr, "path not reachable (%s method): %s\n", toString(plan.method),
                     plan.problem.c_str());
        return kUnreachable;
    }
    const auto program = buildPipeRobotProgram(job, plan, text);

    std::vector<std::unique_ptr<SimulatedDrive>> drives;
    EngineDevices devices;
    // CANopen drives (the job's devices section or --devices canopen): always real time.
    const bool overCan = usesCanOpen(o.devices.devices, job);
    const CanRunOptions& canOptions = o.devices.can;
    // Any ending (signal, std::terminate) first stops the torch and disables the drives.
    SafeShutdown::install();
    CanEngineDevices can;
    std::string canError;
    if (overCan && !can.start(job, canOptions, &canError)) {
        std::fprintf(stderr, "cutcell-cli run over CANopen: %s\n", canError.c_str());
        return kFailure;
    }
    for (int i = 0; overCan && i < kAxisCount; ++i)
        devices.axes[static_cast<size_t>(i)] = can.axis(i);
    for (int i = 0; !overCan && i < kAxisCount; ++i) {
        SimulatedDriveConfig dc;
        dc.gains = job.controller[static_cast<size_t>(i)];
        dc.plant = job.plant[static_cast<size_t>(i)];
        dc.period_s = job.sim.period_s;
        dc.initial_position = program->reference[i];
        drives.push_back(std::make_unique<SimulatedDrive>(dc));
        devices.axes[static_cast<size_t>(i)] = drives.back().get();
    }
    SimulatedTorch torch;
    devices.torch = &torch;

    EngineConfig config;
    config.period_s = job.sim.period_s;
    if (overCan) {
        can.tune(config, job);
        realtime = true;
    }
    config.clock = realtime ? ClockMode::RealTime : ClockMode::AsFastAsPossible;
    config.spec = job.engine;
    config.realtime = rtSettings;
    MotionEngine engine(devices, config);
    struct EngineAttachment { // detached before the engine goes
        CanEngineDevices& can;
        ~EngineAttachment() { can.attachEngine(nullptr); }
    } attachment{can};
    can.attachEngine(&engine);
    const SafeShutdown::Registration safeStop = SafeShutdown::add([&](const std::string& why) {
        if (overCan) {
            can.safeStop(why);
            return;
        }
        engine.emergencyStop(); // simulated drives: the engine stops torch and drives
        const std::string line = "program ending (" + why + "): emergency stop";
        std::fprintf(stderr, "cutcell-cli: %s\n", line.c_str());
        engine.logExternalEvent(Severity::Error, line);
    });
    if (realtime) engine.startThread();
    // Generous bound per step: approach, settling and the cut.
    const double budget_s = 60 + 2 * plan.cut_time_s;
    const auto step = [&](EngineState target) {
        return runUntil(engine, realtime, target, budget_s, quiet);
    };
    bool ok = engine.load(program) && engine.enable() && step(EngineState::Ready);
    ok = ok && engine.home() && step(EngineState::Ready);
    ok = ok && engine.start() && step(EngineState::Completed);
    if (realtime) engine.stopThread();
    (void)ok;
    engine.flushRunLog();
    printEvents(engine, quiet);
    if (const int sig = SafeShutdown::requestedSignal()) {
        std::fprintf(stderr, "cutcell-cli run: stopped by %s\n", SafeShutdown::signalName(sig));
        return 128 + sig;
    }

    TrackingReport report;
    std::string outcome;
    if (engine.state() != EngineState::Completed || !engine.lastRunReport(report, &outcome)) {
        std::fprintf(stderr, "cutcell-cli run: the run did not complete (state %s)\n",
                     toString(engine.state()));
        return kFailure;
    }
    report.method = toString(job.method);
    report.max_direction_deviation_deg = plan.max_deviation_deg;
    const CycleStats cs = engine.cycleStats();
    const std::string dir = engine.lastRunDirectory();
    if (!dir.empty()) std::fprintf(stderr, "run log: %s\n", dir.c_str());
    std::fprintf(stderr,
                 "%s: %llu cycles, %llu overruns, jitter p99 %.1f us, telemetry dropped %llu\n",
                 outcome.c_str(), static_cast<unsigned long long>(cs.cycles),
                 static_cast<unsigned long long>(cs.overruns), cs.jitter_us_p99,
                 static_cast<unsigned long long>(cs.telemetry_dropped));
    const std::string out = json::write(reportToJson(report));
    const std::string& reportFile = o.report;
    if (const int rc = emitReport(reportFile, out, "run"); rc != kOk || reportFile.empty())
        return rc;
    return kOk;
}

} // namespace cutcell::cli
