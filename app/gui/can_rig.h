#pragma once
// The CANopen cell behind the GUI: a CANopen master (the job's devices section, SYNC posted by
// the engine's last drive write, as `cutcell-cli run --devices canopen`), its six CiA 402
// axes and the simulated torch, wired into a real-time motion engine started here. The bus is
// not touched here: the rig's link (can_link.h) brings it up on request, off the GUI thread.
#include "ui/engine_rig.h"

namespace cutcell::app {

// Null with *error set on a configuration the bus cannot carry: the bus load over the limit
// with the figures, a plugin or interface that does not exist.
std::unique_ptr<CutCell::ui::EngineRig> makeCanRig(const Job& job, std::string* error);

} // namespace cutcell::app
