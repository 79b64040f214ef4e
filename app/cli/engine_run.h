#pragma once
// A planned job run through the motion engine — load, enable, home, start, completed — on the
// machine's simulated rig or on its CANopen cell. The engine is the only cycle: `cutcell-cli
// run` and `cutcell-cli simulate --devices canopen` both come here.
//
// Clocks: the wall clock (the engine's own real-time thread), or lock-step (this thread runs
// the engine one cycle at a time; on CAN it waits after each cycle until every node has
// answered that cycle's SYNC, so the run goes as fast as the bus answers and its figures do
// not depend on how the host schedules threads). The engine's cycle itself never waits.
#include "can_run.h"

#include "core/engine/engine_types.h"
#include "core/engine/realtime_thread.h"
#include "core/job/job.h"
#include "core/json/json.h"
#include "core/machine/machine_module.h"
#include "core/record/run_record.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace cutcell {
class MotionEngine;
}

namespace cutcell::cli {

struct EngineRunSetup {
    const char* command = "run"; // names the command in messages ("cutcell-cli run: ...")
    bool over_can = false;       // the machine's CANopen cell instead of its simulated rig
    CanRunOptions can;           // over_can: plugin, interface, period, clock, --drivesim
    bool realtime = false;       // the simulated rig paced by the wall clock (CAN: can.realtime)
    bool quiet = false;          // events of severity Info not printed
    RealtimeSettings rt;         // the engine thread's set-up (real-time clock only)
    std::shared_ptr<RunRecordSink> record; // the production record (null: none)
    // Each telemetry sample as it is drained (~30 Hz batches, on this thread): the shop-floor
    // link publishes from it; it may command the engine (a remote feed hold).
    std::function<void(MotionEngine&, const TelemetrySample&)> on_telemetry;
};

struct EngineRunResult {
    int code = 1;         // ExitCode: kOk once the run completed
    json::Value report;   // the module's run report with the rig's or the cell's own figures
    CycleStats cycles;    // the engine's
    bool realtime = true; // which clock ran it
    // Over CAN: what the bus carried.
    std::uint64_t frames_tx = 0, frames_rx = 0;
    double sync_jitter_us_p99 = 0;
    double wall_s = 0;
};

// Runs the plan; prints the events (stderr) and the run's summary line. The job's
// engine.runs_dir says where the run log goes ("" = none).
EngineRunResult runOnEngine(const Job& job, const MachineModule& module, const MachinePlan& plan,
                            const EngineRunSetup& setup);

} // namespace cutcell::cli
