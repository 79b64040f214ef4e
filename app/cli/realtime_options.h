#pragma once
// Command-line settings of the engine thread's real-time set-up (run, bench):
//   --rt-priority N   SCHED_FIFO priority 1..99, 0 = normal scheduler (default 80)
//   --rt-cpu N        pin the engine thread to CPU N (default: not pinned)
//   --rt-dma-latency  hold /dev/cpu_dma_latency at 0 us while the engine runs
//   --no-mlock        do not lock memory
#include "core/engine/realtime_thread.h"

#include <CLI/CLI.hpp>

namespace cutcell::cli {

// Declares the four options on `cmd`; CLI11 checks the ranges (priority 0..99, an existing CPU)
// and refuses anything else with exit 64.
void addRealtimeOptions(CLI::App& cmd, RealtimeSettings& s);

} // namespace cutcell::cli
