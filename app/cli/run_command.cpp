// cutcell-cli run: executes a job through the motion engine with the machine's simulated rig
// or its CANopen cell (load -> enable -> home -> start -> completed), writes the run log and
// prints the report (engine_run.cpp runs it).
#include "cli_commands.h"
#include "engine_run.h"

#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/machine_registry.h"
#include "devices/record/consumable_run_sink.h"
#include "devices/record/run_record_store.h"

#include <cstdio>
#include <filesystem>

namespace cutcell::cli {
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
    if (!o.runs.empty()) job.engine.runs_dir = o.runs;

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
        std::fprintf(stderr, "%s\n", plan.outcome.message.c_str());
        return kUnreachable;
    }
    EngineRunSetup setup;
    setup.command = "run";
    setup.over_can = overCan;
    setup.can = o.devices.can;
    setup.realtime = o.realtime;
    setup.quiet = o.quiet;
    setup.rt = o.rt; // the engine thread's set-up (with --realtime or CANopen)
    if (!o.record.empty()) {
        try {
            auto record = std::make_shared<RunRecordStore>(o.record, RunRecordStore::desktopUser());
            if (record->interruptedAtOpen() > 0)
                std::fprintf(stderr,
                             "run: production record %s: %d run(s) of a killed program "
                             "closed as interrupted\n",
                             record->where().c_str(), record->interruptedAtOpen());
            // The consumables are counted in the same record (issue 24).
            const std::string where = record->where();
            setup.record =
                openConsumableRunSink(std::move(record), where, [](const std::string& m) {
                    std::fprintf(stderr, "run: %s\n", m.c_str());
                });
        } catch (const RecordError& e) {
            std::fprintf(stderr, "run: %s\n", e.what());
            return kFailure;
        }
    }
    const EngineRunResult r = runOnEngine(job, module, plan, setup);
    if (r.code != kOk) return r.code;
    const std::string out = json::write(r.report);
    const std::string& reportFile = o.report;
    if (const int rc = emitReport(reportFile, out, "run"); rc != kOk || reportFile.empty())
        return rc;
    return kOk;
}

} // namespace cutcell::cli
