// The pipe robot's CAN cell: six rotary CSP drives with the job's own controller and joint plant.
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "devices/machines/can_cell_machine.h"

namespace cutcell {

bool fillPipeRobotCanCell(CanCellBuilder& b, std::string*) {
    const PipeRobotSpec& spec = pipeRobotSpec(b.job);
    for (int a = 0; a < b.cell.axis_count; ++a) {
        const auto i = static_cast<size_t>(a);
        b.cell.sim_drives.push_back(b.driveNode(a, spec.controller[i], spec.plant[i]));
    }
    return true;
}

} // namespace cutcell
