// The machines of the operator station: one line per machine (README, "Adding a machine").
#include "ui/machine/machine_ui_registry.h"
#include "ui/machines/flying_saw/flying_saw_ui.h"
#include "ui/machines/pipe_robot/pipe_robot_ui.h"
#include "ui/machines/profile_cutter/profile_cutter_ui.h"
#include "ui/machines/quick_return/quick_return_ui.h"
#include "ui/machines/section_steel/section_steel_ui.h"

namespace CutCell::ui {

void registerMachineUis(MachineUiRegistry& registry) {
    registry.add(std::make_unique<PipeRobotUi>());
    registry.add(std::make_unique<ProfileCutterUi>());
    registry.add(std::make_unique<QuickReturnUi>());
    registry.add(std::make_unique<FlyingSawUi>());
    registry.add(std::make_unique<SectionSteelUi>());
}

} // namespace CutCell::ui
