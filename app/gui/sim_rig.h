#pragma once
// The factory the main window uses: the job's machine's simulated rig (devices/machines/),
// or the CANopen cell (can_rig.h) for a job with devices.kind = "canopen".
#include "ui/engine_rig.h"

namespace cutcell::app {

std::unique_ptr<CutCell::ui::EngineRig> makeRig(const Job& job, ClockMode clock,
                                                std::string* error);

} // namespace cutcell::app
