#pragma once
// Real-time set-up of the engine thread, checked and reported (never silent):
//  - SCHED_FIFO at a priority (needs CAP_SYS_NICE or an rtprio limit; the return value of
//    pthread_setschedparam says whether it was granted),
//  - mlockall(MCL_CURRENT | MCL_FUTURE) and a pre-faulted stack, so the cycle takes no page
//    fault (skipped in sanitizer builds: ASan's shadow memory cannot be locked),
//  - optionally pinned to one CPU and /dev/cpu_dma_latency held at 0 us while the thread runs
//    (keeps the CPU out of deep idle states; needs write access to the device, usually root).
// What ros2_control's realtime_tools and LinuxCNC do before their loops start.
#include <array>
#include <cstddef>
#include <string_view>

namespace cutcell {

struct RealtimeSettings {
    int priority = 80;            // SCHED_FIFO priority 1..99; 0 = stay on the normal scheduler
    bool lock_memory = true;      // mlockall + pre-fault the stack
    int cpu = -1;                 // pin the engine thread to this CPU; -1 = no pinning
    bool cpu_dma_latency = false; // hold /dev/cpu_dma_latency at 0 us while running
};

// What the set-up got. errno values are 0 when the step succeeded or was not asked for.
struct RealtimeStatus {
    bool applied = false; // a real-time engine thread ran the set-up
    bool rt_priority_granted = false;
    int priority = 0; // the SCHED_FIFO priority granted
    int priority_error = 0;
    bool memory_locked = false;
    int lock_error = 0;
    bool cpu_pinned = false;
    int cpu = -1;
    int cpu_error = 0;
    bool dma_latency_held = false;
    int dma_latency_error = 0;
};

// Runs on the thread to set up. Returns the status; `dmaFd` receives the open
// /dev/cpu_dma_latency descriptor (-1 if none) that releaseRealtime() closes.
RealtimeStatus applyRealtime(const RealtimeSettings& s, int* dmaFd);
void releaseRealtime(int dmaFd);

// One line for the event log, e.g. "Real-time: SCHED_FIFO 80 granted; memory locked; ...":
// items joined by "; ", each a whole sentence. Returns true when every requested step
// succeeded. A refusal with the OS's reasons runs to about 300 characters.
bool describeRealtime(const RealtimeSettings& s, const RealtimeStatus& st, char* out,
                      unsigned long size);

// The length of the first piece of `line` that fits in maxChars, cut before a "; " between
// items (an item longer than maxChars is cut at maxChars). The engine emits the line in events
// of this size; the next piece starts after the "; ".
std::size_t realtimeLinePiece(std::string_view line, std::size_t maxChars);

} // namespace cutcell
