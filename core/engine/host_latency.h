#pragma once
// This machine's wake-up latency, measured the way cyclictest does (-m -p PRIO -i PERIOD
// -D DURATION): a SCHED_FIFO thread with memory locked sleeps with clock_nanosleep to
// absolute CLOCK_MONOTONIC deadlines one period apart and records how late it woke. The
// engine's cycle jitter is the same measurement on its own thread, so their ratio says how
// much the engine adds to what the host gives (1 = nothing), and the host's p99 alone says
// whether the machine suits a period at all.
#include "core/engine/realtime_thread.h"

#include <cstdint>

namespace cutcell {

struct HostLatency {
    std::uint64_t samples = 0;
    double p50_us = 0;
    double p99_us = 0;
    double max_us = 0;
    RealtimeStatus realtime; // what the measuring thread was granted
};

// Blocks for `duration_s`; runs the measurement on a thread of its own with `settings`
// (priority, memory lock, CPU) as the engine would be set up.
HostLatency measureHostWakeupLatency(double period_s, double duration_s,
                                     const RealtimeSettings& settings);

} // namespace cutcell
