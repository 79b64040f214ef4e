// The section-steel cutter's CAN cell: its eight rotary CSP drives, each with the job's own
// controller and joint plant.
#include "core/machines/section_steel/section_steel_spec.h"
#include "devices/machines/can_cell_machine.h"

namespace cutcell {

bool fillSectionSteelCanCell(CanCellBuilder& b, std::string* error) {
    const auto* steel = b.job.machine_spec.as<section_steel::SectionSteelSpec>();
    if (!steel) {
        if (error) *error = "the job holds no section-steel section";
        return false;
    }
    for (int a = 0; a < b.cell.axis_count; ++a) {
        canopen::DriveNodeConfig d = b.driveNode(a, steel->controller[static_cast<size_t>(a)],
                                                 steel->plant[static_cast<size_t>(a)]);
        d.start_position_rad = b.startOf(a);
        b.cell.sim_drives.push_back(d);
    }
    return true;
}

} // namespace cutcell
