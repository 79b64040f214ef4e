#include "engine_run.h"

#include "cli_commands.h"

#include "core/engine/motion_engine.h"
#include "core/engine/run_log.h"
#include "devices/machines/can_cells.h"
#include "devices/machines/sim_rig_registry.h"
#include "devices/process/safe_shutdown.h"
#include "devices/sim/simulated_torch.h"

#include "can_devices.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>

namespace cutcell::cli {

namespace {

using SteadyClock = std::chrono::steady_clock;

void printEvents(MotionEngine& engine, bool quiet) {
    EngineEvent e;
    while (engine.popEvent(e))
        if (!quiet || e.severity != Severity::Info)
            std::fprintf(stderr, "%s\n", RunLog::formatEvent(e).c_str());
}

bool latched(EngineState s) {
    return s == EngineState::Fault || s == EngineState::EmergencyStop;
}

// How the engine is paced: its own thread on the wall clock, or this thread cycle by cycle
// (on CAN each cycle awaited on the bus).
struct Pace {
    bool realtime = false;
    CanEngineDevices* lockStepBus = nullptr;
    const std::function<void(MotionEngine&, const TelemetrySample&)>* on_telemetry = nullptr;
};

// Runs the engine (on this thread, or waits for its thread) until it reaches `target`; gives
// up on a latch, a signal, the bus or after budget_s of engine time. Telemetry is drained as a
// GUI would. *why: what stopped it, when it was not the engine (which says so in its events).
bool runUntil(MotionEngine& engine, const Pace& pace, EngineState target, double budget_s,
              bool quiet, std::string* why) {
    const double period = engine.cycleStats().period_s;
    const auto chunk = static_cast<std::uint64_t>(0.033 / period) + 1; // a 30 Hz drain
    const auto t0 = SteadyClock::now();
    const std::uint64_t c0 = engine.cycleStats().cycles;
    bool first = true;
    for (;;) {
        if (pace.realtime) {
            std::this_thread::sleep_for(std::chrono::milliseconds(33));
        } else if (pace.lockStepBus) {
            // The first cycle takes the pending command even if the state already equals target.
            for (std::uint64_t k = 0; k < chunk; ++k) {
                const std::uint64_t sent = pace.lockStepBus->master().cyclesSent();
                const EngineState s = engine.runCycles(1, target);
                if (!pace.lockStepBus->awaitAnswers(sent, why)) {
                    engine.emergencyStop(); // latched by one more cycle: tool off, drives stop
                    engine.runCycles(1, EngineState::EmergencyStop);
                    printEvents(engine, quiet);
                    return false;
                }
                if ((s == target && !first) || latched(s)) break;
                first = false;
            }
        } else {
            if (first) engine.runCycles(1, target);
            engine.runCycles(chunk, target);
        }
        first = false;
        TelemetrySample t;
        while (engine.popTelemetry(t))
            if (pace.on_telemetry && *pace.on_telemetry) (*pace.on_telemetry)(engine, t);
        printEvents(engine, quiet);
        if (!pace.realtime) engine.flushRunLog();          // the thread mode has its own logger
        if (SafeShutdown::requestedSignal()) return false; // the safe stop has run: end
        const EngineState s = engine.state();
        if (s == target) return true;
        if (latched(s)) return false;
        const double elapsed = pace.realtime
                                   ? std::chrono::duration<double>(SteadyClock::now() - t0).count()
                                   : static_cast<double>(engine.cycleStats().cycles - c0) * period;
        if (elapsed > budget_s) {
            char text[160];
            std::snprintf(text, sizeof text, "%s not reached within %.0f s (state %s)",
                          toString(target), budget_s, toString(s));
            *why = text;
            return false;
        }
    }
}

} // namespace

EngineRunResult runOnEngine(const Job& job, const MachineModule& module, const MachinePlan& plan,
                            const EngineRunSetup& setup) {
    EngineRunResult result;
    const auto t0 = SteadyClock::now();
    const auto program = plan.program;
    const std::string command = std::string("cutcell-cli ") + setup.command;
    bool realtime = setup.over_can ? setup.can.realtime : setup.realtime;
    result.realtime = realtime;

    EngineDevices devices;
    EngineConfig config;
    config.period_s = job.sim.period_s;
    config.spec = job.engine; // first: the bus's tuning reads its speed limits
    if (const Outcome can = module.canOpen(); setup.over_can && !can.ok()) {
        std::fprintf(stderr, "%s --devices canopen: %s\n", command.c_str(), can.message.c_str());
        result.code = kInvalidJob;
        return result;
    }
    // Any ending (signal, std::terminate) first stops the tool and disables the drives.
    SafeShutdown::install();
    CanEngineDevices can;
    SimulatedTorch canTorch; // the torch is simulated on the CAN path as well
    std::unique_ptr<MachineSimRig> rig;
    std::unique_ptr<CanCellMeter> canMeter;
    if (setup.over_can) {
        std::string canError;
        if (!can.start(job, setup.can, program.get(), &canError)) {
            std::fprintf(stderr, "%s over CANopen: %s\n", command.c_str(), canError.c_str());
            return result;
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
        if (!setup.quiet) std::fprintf(stderr, "CANopen cell: %s\n", can.description().c_str());
    } else {
        std::string error;
        rig = makeSimulatedRig(job, *program, &error);
        if (!rig) {
            std::fprintf(stderr, "%s: %s\n", command.c_str(), error.c_str());
            return result;
        }
        devices = rig->devices();
        rig->configure(config);
    }
    config.clock = realtime ? ClockMode::RealTime : ClockMode::AsFastAsPossible;
    config.spec = job.engine;
    config.realtime = setup.rt;
    MotionEngine engine(devices, config);
    if (setup.record) engine.setRunRecord(setup.record);
    struct EngineAttachment { // detached before the engine goes
        CanEngineDevices& can;
        ~EngineAttachment() { can.attachEngine(nullptr); }
    } attachment{can};
    can.attachEngine(&engine);
    const SafeShutdown::Registration safeStop = SafeShutdown::add([&](const std::string& why) {
        if (setup.over_can) {
            can.safeStop(why);
            return;
        }
        engine.emergencyStop(); // simulated drives: the engine stops the tool and the drives
        const std::string line = "program ending (" + why + "): emergency stop";
        std::fprintf(stderr, "cutcell-cli: %s\n", line.c_str());
        engine.logExternalEvent(Severity::Error, line);
    });
    if (realtime) engine.startThread();
    // Generous bound per step: approach, settling and the cut.
    const double budget_s = 60 + 2 * program->cut_time_s;
    const Pace pace{realtime, setup.over_can && !realtime ? &can : nullptr, &setup.on_telemetry};
    std::string stopped;
    const auto step = [&](EngineState target) {
        return runUntil(engine, pace, target, budget_s, setup.quiet, &stopped);
    };
    bool ok = engine.load(program) && engine.enable() && step(EngineState::Ready);
    ok = ok && engine.home() && step(EngineState::Ready);
    ok = ok && engine.start() && step(EngineState::Completed);
    // A signal's safe stop latches the E-STOP before it has disabled the drives and logged:
    // wait for it, so the run ends as stopped by the signal and its last line is logged.
    const int sig = SafeShutdown::requestedSignalAfterActions(2000);
    if (realtime) engine.stopThread();
    // Lock-step: no cycle follows the one that stopped, so every node gets its quick stop now.
    if (!ok && pace.lockStepBus && !sig) {
        can.master().emergencyStop(false);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    engine.flushRunLog();
    printEvents(engine, setup.quiet);
    if (sig) {
        std::fprintf(stderr, "%s: stopped by %s\n", command.c_str(), SafeShutdown::signalName(sig));
        result.code = 128 + sig;
        return result;
    }

    TrackingReport report;
    std::string outcome;
    if (engine.state() != EngineState::Completed || !engine.lastRunReport(report, &outcome)) {
        std::fprintf(stderr, "%s: the run did not complete (state %s)%s%s\n", command.c_str(),
                     toString(engine.state()), stopped.empty() ? "" : ": ", stopped.c_str());
        return result;
    }
    result.cycles = engine.cycleStats();
    const CycleStats& cs = result.cycles;
    const std::string dir = engine.lastRunDirectory();
    if (!dir.empty()) std::fprintf(stderr, "run log: %s\n", dir.c_str());
    std::fprintf(
        stderr, "%s: %llu cycles, %llu overruns, jitter p99 %.1f us, telemetry dropped %llu\n",
        rig        ? rig->summary(outcome).c_str()
        : canMeter ? canMeter->summary(outcome).c_str()
                   : outcome.c_str(),
        static_cast<unsigned long long>(cs.cycles), static_cast<unsigned long long>(cs.overruns),
        cs.jitter_us_p99, static_cast<unsigned long long>(cs.telemetry_dropped));
    result.report = module.runReport(job, plan, report);
    if (rig) rig->addToReport(result.report);
    if (canMeter) canMeter->addToReport(result.report);
    if (setup.over_can) {
        const canopen::MasterStats ms = can.master().stats();
        result.frames_tx = ms.frames_tx;
        result.frames_rx = ms.frames_rx;
        result.sync_jitter_us_p99 = ms.sync_jitter_us_p99;
    }
    result.wall_s = std::chrono::duration<double>(SteadyClock::now() - t0).count();
    result.code = kOk;
    return result;
}

} // namespace cutcell::cli
