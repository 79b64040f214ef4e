// The one list of machines. Adding a machine = one line here (and its folder); the first one
// is the machine of schema-1 files without a "machine" key.
#include "core/machine/machine_registry.h"
#include "core/machines/flying_saw/flying_saw_module.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"
#include "core/machines/quick_return/quick_return_module.h"
#include "core/machines/section_steel/section_steel_module.h"

namespace cutcell {

void registerMachines() {
    registerMachine(std::make_unique<PipeRobotModule>());
    registerMachine(std::make_unique<ProfileCutterModule>());
    registerMachine(std::make_unique<QuickReturnModule>());
    registerMachine(std::make_unique<FlyingSawModule>());
    registerMachine(std::make_unique<SectionSteelModule>());
}

} // namespace cutcell
