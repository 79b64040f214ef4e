#pragma once
// CAN figures of cutcell-cli bench: the master against the drive simulator on a private
// virtualcan bus (its own TCP port, so other users of can0 on this machine are not disturbed).
#include "core/json/json.h"

namespace cutcell::cli {

// Adds can_frames_per_s (sustained, lock-step cycles), can_cycle_jitter_us_p99 (SYNC produced
// by the pacing thread), can_estop_latency_us_p50/_p99 (quickStop() of all six drives -> the
// last stop frame heard by an independent listener on the bus) and the cycle used.
void benchCan(json::Object& out, bool quick);

} // namespace cutcell::cli
