#pragma once
// The simulated cell behind the GUI: six simulated drives (the job's PID and joint plant) and
// a simulated torch wired into a motion engine whose thread is started here.
#include "ui/engine_rig.h"

namespace cutcell::app {

// The factory the main window uses; CANopen drives are refused with a message until the
// CAN layer is wired here.
std::unique_ptr<CutCell::ui::EngineRig> makeRig(const Job& job, ClockMode clock,
                                                std::string* error);

} // namespace cutcell::app
