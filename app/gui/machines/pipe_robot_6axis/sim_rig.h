#pragma once
// The simulated pipe-cutting robot cell (seed 000) behind the GUI: six simulated drives (the
// job's PID and joint plant) and a simulated torch wired into a motion engine whose thread is
// started here.
#include "ui/engine_rig.h"

namespace cutcell::app {

// Null with *error set when the rig cannot be built.
std::unique_ptr<CutCell::ui::EngineRig> makePipeRobotSimRig(const Job& job, ClockMode clock,
                                                            std::string* error);

} // namespace cutcell::app
