#pragma once
// The CANopen options of `cutcell-cli simulate` and `run` (--devices canopen): the bus, the
// engine's cycle on it and its clock. Both commands run the machine's program through the
// motion engine on the machine's CAN cell (engine_run.h); the engine is the only cycle.
//
// CSP timing: a set-point written before SYNC k is reached by the drive at SYNC k+1, and the
// position in the TPDO of SYNC k is sampled at SYNC k; the engine's CAN tuning
// (devices/canopen/engine_tuning.h) allows for it.
#include "core/job/job.h"

#include <string>

namespace cutcell::cli {

struct CanRunOptions {
    std::string plugin;    // empty: job.devices.can_plugin
    std::string interface; // empty: job.devices.can_interface
    double period_s = 0;   // SYNC period = the engine's cycle; 0: job.sim.period_s
    // The engine paced by the wall clock (its real-time thread), or lock-step: one cycle, then
    // every node's answer to its SYNC, as fast as the bus answers.
    bool realtime = true;
    bool in_process_simulator = false; // start a drive simulator on its own thread (a bus peer)
};

// Whether a command runs over CANopen: --devices canopen|simulated (checked by the parser),
// else (empty) the job's choice.
bool usesCanOpen(const std::string& devices, const Job& job);

} // namespace cutcell::cli
