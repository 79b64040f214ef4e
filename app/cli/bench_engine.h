#pragma once
// The motion engine's part of `cutcell-cli bench` (bench_engine.cpp).
#include "core/job/job.h"
#include "core/json/json.h"

namespace cutcell::cli {

void benchEngine(const Job& job, bool quick, json::Object& out);

} // namespace cutcell::cli
