// The machines' CAN cells: one line per machine (README, "Adding a machine"), as
// sim_rig_registry.cpp lists their simulated rigs.
#include "core/machines/flying_saw/flying_saw_module.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"
#include "core/machines/quick_return/quick_return_spec.h"
#include "core/machines/section_steel/section_steel_module.h"
#include "devices/machines/can_cell_machine.h"

namespace cutcell {
namespace {

const CanCellEntry kCells[] = {
    {kPipeRobotId, fillPipeRobotCanCell, nullptr},
    {kSectionSteelId, fillSectionSteelCanCell, nullptr},
    {kFlyingSawId, fillFlyingSawCanCell, makeFlyingSawCanMeter},
    {kQuickReturnId, fillQuickReturnCanCell, nullptr},
};

} // namespace

const CanCellEntry* findCanCell(const std::string& machineId) {
    for (const CanCellEntry& e : kCells)
        if (machineId == e.machine) return &e;
    return nullptr;
}

} // namespace cutcell
