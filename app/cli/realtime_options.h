#pragma once
// Command-line settings of the engine thread's real-time set-up (run, bench):
//   --rt-priority N   SCHED_FIFO priority 1..99, 0 = normal scheduler (default 80)
//   --rt-cpu N        pin the engine thread to CPU N (default: not pinned)
//   --rt-dma-latency  hold /dev/cpu_dma_latency at 0 us while the engine runs
//   --no-mlock        do not lock memory
#include "cli_commands.h"
#include "core/engine/realtime_thread.h"

namespace cutcell::cli {

inline const std::vector<std::string> kRealtimeValueOptions{"--rt-priority", "--rt-cpu"};

// kOk, or kUsage with the flag, the value and the limit on stderr.
int parseRealtimeOptions(const Args& args, RealtimeSettings& s, const char* command);

} // namespace cutcell::cli
