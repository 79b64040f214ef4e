#pragma once
// The simulated 2-axis NC pipe profile cutter behind the GUI (the profile cutter machine):
// the job's ProfileCutterRig (A and X open-loop steppers behind a pulse card, and a torch)
// wired into a motion engine whose thread is started here.
#include "ui/engine_rig.h"

namespace cutcell::app {

// Null with *error set (the core's message naming key, value and limit) when the job's cut
// cannot be built.
std::unique_ptr<CutCell::ui::EngineRig> makeProfileCutterRig(const Job& job, ClockMode clock,
                                                             std::string* error);

} // namespace cutcell::app
