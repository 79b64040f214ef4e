#pragma once
// The CANopen cell behind the GUI: a CANopen master (the job's devices section, SYNC posted by
// the engine's last drive write, as `cutcell-cli run --devices canopen`), its six CiA 402
// axes and the simulated torch, wired into a real-time motion engine started here.
#include "ui/engine_rig.h"

namespace cutcell::app {

// Null with *error set (bus load over the limit with the figures, no connection, a node that
// did not become operational) on failure.
std::unique_ptr<CutCell::ui::EngineRig> makeCanRig(const Job& job, std::string* error);

} // namespace cutcell::app
