#include "realtime_options.h"

#include <string>
#include <thread>

namespace cutcell::cli {

void addRealtimeOptions(CLI::App& cmd, RealtimeSettings& s) {
    const int cpus = static_cast<int>(std::thread::hardware_concurrency());
    const int lastCpu = cpus > 0 ? cpus - 1 : 1023;
    cmd.add_option("--rt-priority", s.priority,
                   "engine thread SCHED_FIFO priority, 0 = normal scheduler (default 80)")
        ->check(CLI::Range(0, 99))
        ->type_name("0-99");
    cmd.add_option("--rt-cpu", s.cpu, "pin the engine thread to this CPU")
        ->check(CLI::Range(0, lastCpu))
        ->type_name("0-" + std::to_string(lastCpu));
    cmd.add_flag("--rt-dma-latency", s.cpu_dma_latency,
                 "hold /dev/cpu_dma_latency at 0 us while the engine runs");
    cmd.add_flag_callback(
        "--no-mlock", [&s] { s.lock_memory = false; }, "do not lock the process memory");
}

} // namespace cutcell::cli
