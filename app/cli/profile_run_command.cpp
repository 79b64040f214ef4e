// cutcell-cli run for the 2-axis profile cutter: the job's program through the motion engine on
// simulated stepper axes (ProfileCutterRig), load -> enable -> home -> start -> completed, with
// the run log and the JSON report as for the robot. Called by runRun() for its machine.
#include "cli_commands.h"

#include "core/engine/motion_engine.h"
#include "core/engine/run_log.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machines/profile_cutter_program.h"
#include "devices/sim/profile_cutter_rig.h"

#include <chrono>
#include <cstdio>
#include <thread>

namespace cutcell::cli {
namespace {

// Runs (or waits for) the engine until `target`, a latched stop or budget_s of engine time,
// draining telemetry and printing warnings and faults as a GUI would.
bool runUntil(MotionEngine& engine, bool realtime, EngineState target, double budget_s,
              bool quiet) {
    const double period = engine.cycleStats().period_s;
    const auto chunk = static_cast<std::uint64_t>(0.033 / period) + 1;
    const auto t0 = std::chrono::steady_clock::now();
    const std::uint64_t c0 = engine.cycleStats().cycles;
    for (bool first = true;; first = false) {
        if (realtime)
            std::this_thread::sleep_for(std::chrono::milliseconds(33));
        else
            engine.runCycles(first ? 1 : chunk, target);
        TelemetrySample t;
        while (engine.popTelemetry(t)) {
        }
        EngineEvent e;
        while (engine.popEvent(e))
            if (!quiet || e.severity != Severity::Info)
                std::fprintf(stderr, "%s\n", RunLog::formatEvent(e).c_str());
        const EngineState s = engine.state();
        if (s == target) return true;
        if (s == EngineState::Fault || s == EngineState::EmergencyStop) return false;
        const double elapsed =
            realtime ? std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()
                     : static_cast<double>(engine.cycleStats().cycles - c0) * period;
        if (elapsed > budget_s) return false;
    }
}

} // namespace

int runProfileRun(const Job& job, const std::string& jobText, const RunOptions& o) {
    std::shared_ptr<const MotionProgram> program;
    try {
        program = buildProfileCutterProgram(job, jobText);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "invalid job: %s\n", e.what());
        return kInvalidJob;
    }
    const bool realtime = o.realtime, quiet = o.quiet;
    ProfileCutterRig rig(job, *program);
    EngineConfig config;
    rig.configure(config);
    config.clock = realtime ? ClockMode::RealTime : ClockMode::AsFastAsPossible;
    config.spec = job.engine;
    if (!o.runs.empty()) config.spec.runs_dir = o.runs;
    MotionEngine engine(rig.devices(), config);
    if (realtime) engine.startThread();
    const double budget_s = 60 + 2 * program->cut_time_s;
    auto step = [&](EngineState target) {
        return runUntil(engine, realtime, target, budget_s, quiet);
    };
    bool ok = engine.load(program) && engine.enable() && step(EngineState::Ready);
    ok = ok && engine.home() && step(EngineState::Ready);
    ok = ok && engine.start() && step(EngineState::Completed);
    if (realtime) engine.stopThread();
    engine.flushRunLog();

    TrackingReport report;
    std::string outcome;
    if (!ok || engine.state() != EngineState::Completed ||
        !engine.lastRunReport(report, &outcome)) {
        std::fprintf(stderr, "cutcell-cli run: the run did not complete (state %s)\n",
                     toString(engine.state()));
        return kFailure;
    }
    const std::string dir = engine.lastRunDirectory();
    if (!dir.empty()) std::fprintf(stderr, "run log: %s\n", dir.c_str());
    std::fprintf(
        stderr,
        "%s: A %lld pulses (%llu sent), X %lld pulses (%llu sent), card at its limit %llu cycles\n",
        outcome.c_str(), static_cast<long long>(rig.a().pulsePosition()),
        static_cast<unsigned long long>(rig.a().pulsesSent()),
        static_cast<long long>(rig.x().pulsePosition()),
        static_cast<unsigned long long>(rig.x().pulsesSent()),
        static_cast<unsigned long long>(rig.a().rateLimitedCycles() + rig.x().rateLimitedCycles()));
    json::Value doc = profileRunReportJson(report);
    doc.set("pulses", json::Object{{"a_position", static_cast<double>(rig.a().pulsePosition())},
                                   {"a_sent", static_cast<double>(rig.a().pulsesSent())},
                                   {"x_position", static_cast<double>(rig.x().pulsePosition())},
                                   {"x_sent", static_cast<double>(rig.x().pulsesSent())},
                                   {"rate_limited_cycles",
                                    static_cast<double>(rig.a().rateLimitedCycles() +
                                                        rig.x().rateLimitedCycles())}});
    const std::string out = json::write(doc);
    const std::string& reportFile = o.report;
    if (const int rc = emitReport(reportFile, out, "run"); rc != kOk || reportFile.empty())
        return rc;
    return kOk;
}

} // namespace cutcell::cli
