#pragma once
// The simulated cell behind the GUI: six simulated drives (the job's PID and joint plant) and
// a simulated torch wired into a motion engine whose thread is started here.
#include "ui/engine_rig.h"

namespace cutcell::app {

// The factory the main window uses: the simulated cell, or the CANopen cell (can_rig.h) for a
// job with devices.kind = "canopen".
std::unique_ptr<CutCell::ui::EngineRig> makeRig(const Job& job, ClockMode clock,
                                                std::string* error);

} // namespace cutcell::app
