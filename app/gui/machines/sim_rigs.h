#pragma once
// The simulated rig of each machine, found by the job's machine id. The rigs live here, in the
// composition root, beside the CAN rig: an EngineRig adapter needs both the ui's interface and
// the devices, and only app/ may see both (devices/ never depends on ui/). The device models
// themselves stay in devices/sim/.
#include "ui/engine_rig.h"

#include <string_view>

namespace cutcell::app {

// The machine's simulated rig factory; empty when this build has none for the machine.
CutCell::ui::EngineRigFactory simulatedRigFor(std::string_view machineId);

} // namespace cutcell::app
