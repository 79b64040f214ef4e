// The pipe robot's CAN cell: six rotary CSP drives with the job's own controller and joint plant.
#include "devices/machines/can_cell_machine.h"

#include <algorithm>
#include <vector>

namespace cutcell {

bool fillPipeRobotCanCell(CanCellBuilder& b, std::string*) {
    std::vector<int> ids;
    for (int a = 0; a < b.cell.axis_count; ++a)
        ids.push_back(b.job.devices.node_ids[static_cast<size_t>(a)]);
    b.cell.sim_drives = canopen::nodesFromJob(b.job, ids);
    for (canopen::DriveNodeConfig& d : b.cell.sim_drives)
        d.max_loop_period_s = std::min(0.001, b.period_s);
    return true;
}

} // namespace cutcell
