#pragma once
// The motion engine's part of `cutcell-cli bench` (bench_engine.cpp).
#include "core/engine/realtime_thread.h"
#include "core/job/job.h"
#include "core/json/json.h"

namespace cutcell::cli {

// `realtime`: the engine thread's set-up, also used for the host's wake-up latency check.
void benchEngine(const Job& job, bool quick, const RealtimeSettings& realtime, json::Object& out);

} // namespace cutcell::cli
