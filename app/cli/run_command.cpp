// cutcell-cli run: executes a job through the motion engine with simulated drives and torch
// (load -> enable -> home -> start -> completed), writes the run log and prints the report.
#include "cli_commands.h"

#include "core/engine/motion_engine.h"
#include "core/engine/run_log.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/machine_registry.h"
#include "devices/machines/can_cells.h"
#include "devices/machines/sim_rig_registry.h"
#include "devices/process/safe_shutdown.h"
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
    bool realtime = o.realtime;
    const bool quiet = o.quiet;
    if (!o.runs.empty()) job.engine.runs_dir = o.runs;
    RealtimeSettings rtSettings = o.rt; // the engine thread's set-up (with --realtime or CANopen)

    // Every machine goes the same way: its module plans, its rig (or CANopen) drives.
    const MachineModule& module = machineFor(job);
    // Over CAN a --period-ms is the engine's cycle: the plan is made for it.
    const bool overCan = usesCanOpen(o.devices.devices, job);
    if (overCan && o.devices.can.period_s > 0) job.sim.period_s = o.devices.can.period_s;
    MachinePlan plan;
    try {
        plan = module.plan(job, text);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "invalid job: %s\n", e.what());
        return kInvalidJob;
    }
    if (!plan.ok()) {
        std::fprintf(stderr, "%s\n", plan.problem.c_str());
        return kUnreachable;
    }
    const auto program = plan.program;

    EngineDevices devices;
    EngineConfig config;
    config.period_s = job.sim.period_s;
    config.spec = job.engine; // first: the bus's tuning reads its speed limits
    // CANopen drives (the job's devices section or --devices canopen): always real time.
    if (std::string noCan; overCan && !module.supportsCanOpen(&noCan)) {
        std::fprintf(stderr, "cutcell-cli run --devices canopen: %s\n", noCan.c_str());
        return kInvalidJob;
    }
    const CanRunOptions& canOptions = o.devices.can;
    // Any ending (signal, std::terminate) first stops the torch and disables the drives.
    SafeShutdown::install();
    CanEngineDevices can;
    SimulatedTorch canTorch; // the torch is simulated on the CAN path as well
    std::unique_ptr<MachineSimRig> rig;
    std::unique_ptr<CanCellMeter> canMeter;
    std::string canError;
    if (overCan) {
        if (!can.start(job, canOptions, program.get(), &canError)) {
            std::fprintf(stderr, "cutcell-cli run over CANopen: %s\n", canError.c_str());
            return kFailure;
        }
        for (int i = 0; i < can.axisCount(); ++i)
            devices.axes[static_cast<size_t>(i)] = can.axis(i);
        for (int k = 0; k < can.sensorCount() && k < kMaxSensors; ++k)
            devices.sensors[static_cast<size_t>(k)] = can.sensor(k);
        devices.torch = &canTorch;
        // The machine's own engine settings (limits, windows), then the bus's margins on top.
        std::string noRig;
        if (const auto machineRig = makeSimulatedRig(job, *program, &noRig))
            machineRig->configure(config);
        can.tune(config, job);
        // The machine's own figures on this cell (the saw's cut lengths), as its rig has them.
        canMeter = makeCanCellMeter(job, *program);
        if (canMeter) canMeter->attach(devices);
        if (!quiet) std::fprintf(stderr, "CANopen cell: %s\n", can.description().c_str());
        realtime = true;
    } else {
        std::string error;
        rig = makeSimulatedRig(job, *program, &error);
        if (!rig) {
            std::fprintf(stderr, "cutcell-cli run: %s\n", error.c_str());
            return kFailure;
        }
        devices = rig->devices();
        rig->configure(config);
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
    const double budget_s = 60 + 2 * program->cut_time_s;
    const auto step = [&](EngineState target) {
        return runUntil(engine, realtime, target, budget_s, quiet);
    };
    bool ok = engine.load(program) && engine.enable() && step(EngineState::Ready);
    ok = ok && engine.home() && step(EngineState::Ready);
    ok = ok && engine.start() && step(EngineState::Completed);
    // A signal's safe stop latches the E-STOP before it has disabled the drives and logged:
    // wait for it, so the run ends as stopped by the signal and its last line is logged.
    const int sig = SafeShutdown::requestedSignalAfterActions(2000);
    if (realtime) engine.stopThread();
    (void)ok;
    engine.flushRunLog();
    printEvents(engine, quiet);
    if (sig) {
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
    const CycleStats cs = engine.cycleStats();
    const std::string dir = engine.lastRunDirectory();
    if (!dir.empty()) std::fprintf(stderr, "run log: %s\n", dir.c_str());
    std::fprintf(
        stderr, "%s: %llu cycles, %llu overruns, jitter p99 %.1f us, telemetry dropped %llu\n",
        rig        ? rig->summary(outcome).c_str()
        : canMeter ? canMeter->summary(outcome).c_str()
                   : outcome.c_str(),
        static_cast<unsigned long long>(cs.cycles), static_cast<unsigned long long>(cs.overruns),
        cs.jitter_us_p99, static_cast<unsigned long long>(cs.telemetry_dropped));
    json::Value doc = module.runReport(job, plan, report);
    if (rig) rig->addToReport(doc);
    if (canMeter) canMeter->addToReport(doc);
    const std::string out = json::write(doc);
    const std::string& reportFile = o.report;
    if (const int rc = emitReport(reportFile, out, "run"); rc != kOk || reportFile.empty())
        return rc;
    return kOk;
}

} // namespace cutcell::cli
