// cutcell-cli simulate JOB --devices canopen: the machine's program through the motion engine on
// its CANopen cell (engine_run.cpp), without a run log; the report is the engine's tracking
// report with what the bus carried.
#include "can_run.h"

#include "cli_commands.h"
#include "engine_run.h"

#include "core/json/json.h"

#include <cstdio>

namespace cutcell::cli {

bool usesCanOpen(const std::string& devices, const Job& job) {
    if (devices.empty()) return job.devices.kind == DeviceKind::CanOpen;
    return devices == "canopen";
}

int runSimulateCan(const Job& plannedJob, const MachineModule& module, const MachinePlan& plan,
                   const SimulateOptions& options) {
    Job job = plannedJob;
    job.engine.runs_dir = ""; // a simulation leaves no run log (`run` does)
    const CanRunOptions& o = options.devices.can;
    EngineRunSetup setup;
    setup.command = "simulate";
    setup.over_can = true;
    setup.can = o;
    setup.quiet = true; // the events' warnings and errors only; the report says the rest
    const EngineRunResult r = runOnEngine(job, module, plan, setup);
    if (r.code != kOk) return r.code;
    json::Value doc = r.report;
    doc.set("devices",
            json::Object{
                {"kind", "canopen"},
                {"can_plugin", o.plugin.empty() ? job.devices.can_plugin : o.plugin},
                {"can_interface", o.interface.empty() ? job.devices.can_interface : o.interface},
                {"period_s", job.sim.period_s},
                {"clock", o.realtime ? "realtime" : "fast"},
                {"frames_tx", static_cast<double>(r.frames_tx)},
                {"frames_rx", static_cast<double>(r.frames_rx)},
                {"wall_s", r.wall_s}});
    if (o.realtime) doc.asObject().back().second.set("sync_jitter_us_p99", r.sync_jitter_us_p99);
    const std::string text = json::write(doc);
    const std::string& reportFile = options.report;
    if (const int rc = emitReport(reportFile, text, "simulate"); rc != kOk || reportFile.empty())
        return rc;
    std::printf("%s over CANopen (%s, period %.1f ms): report written to %s\n", module.id().c_str(),
                o.realtime ? "real time" : "lock-step", job.sim.period_s * 1e3, reportFile.c_str());
    return kOk;
}

} // namespace cutcell::cli
