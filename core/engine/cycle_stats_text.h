#pragma once
// One line of an engine's cycle timing for logs and test output, e.g. "7799 cycles, 10 overruns,
// 311 deadlines missed, jitter p99 3175 us, max 14474 us, work max 9064 us": whether the host
// kept the engine's cycle (a failed real-time run says if it was held up).
#include "core/engine/engine_types.h"

#include <cstdio>
#include <string>

namespace cutcell {

inline std::string cycleTimingLine(const CycleStats& c) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "%llu cycles, %llu overruns, %llu deadlines missed, jitter p99 %.0f us, max %.0f "
                  "us, work max %.0f us",
                  static_cast<unsigned long long>(c.cycles),
                  static_cast<unsigned long long>(c.overruns),
                  static_cast<unsigned long long>(c.missed_deadlines), c.jitter_us_p99,
                  c.jitter_us_max, c.work_us_max);
    return buf;
}

} // namespace cutcell
