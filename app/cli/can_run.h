#pragma once
// A planned cut played over CANopen drives (the job's devices section, or overrides), with
// the same tracking figures as the offline simulation. Until the motion engine drives the
// CAN axes, this runner is the cycle: read the drives -> set-points -> write -> SYNC.
//
// CSP timing: a set-point written before SYNC k is reached by the drive at SYNC k+1, and the
// position in the TPDO of SYNC k is sampled at SYNC k. A cycle that reads SYNC k's feedback and
// then writes therefore reaches its set-point at SYNC k+2: the runner sends the trajectory two
// periods ahead and compares the position of SYNC k with the set-point for t_k (an engine
// driving CAN axes must lead its set-points the same way).
#include "core/job/job.h"
#include "core/sim/tracking_stats.h"
#include "core/trajectory/cut_planner.h"

#include <string>
#include <vector>

namespace cutcell::cli {

struct CanRunOptions {
    std::string plugin;    // empty: job.devices.can_plugin
    std::string interface; // empty: job.devices.can_interface
    double period_s = 0;   // SYNC period; 0: job.sim.period_s
    bool realtime =
        true; // pace SYNCs to the wall clock (false: lock-step, as fast as the bus answers)
    bool in_process_simulator = false; // start a drive simulator on its own thread (a bus peer)
};

struct CanRunResult {
    bool ok = false;
    std::string error; // why the run stopped (bus load, node fault with node and reason, timeout)
    TrackingReport report;
    double sync_jitter_us_p99 = 0;
    std::uint64_t frames_tx = 0, frames_rx = 0;
    double wall_s = 0;
};

CanRunResult runCutOverCan(const Job& job, const CutPlan& plan, const CanRunOptions& options);

// Whether a command runs over CANopen: --devices canopen|simulated (checked by the parser),
// else (empty) the job's choice.
bool usesCanOpen(const std::string& devices, const Job& job);

} // namespace cutcell::cli
