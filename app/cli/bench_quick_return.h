#pragma once
// The quick-return cutter's figures for `cutcell-cli bench`: the MSE of each controller on
// experiment 1 and the velocity error of experiment 2 (default quick-return job).
#include "core/json/json.h"

namespace cutcell::cli {

void benchQuickReturn(json::Object& out);

} // namespace cutcell::cli
