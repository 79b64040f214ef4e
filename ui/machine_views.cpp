#include "ui/machine_views.h"

#include "ui/machine/machine_ui_registry.h"
#include "ui/panels/monitor_views.h"
#include "ui/panels/progress_panel.h"

namespace CutCell::ui {

void adaptViewsToPlan(const std::shared_ptr<const cutcell::MachinePlan>& plan,
                      const cutcell::Job& job, CellViewPanel* cell, PlotsPanel* plots,
                      ProgressPanel* progress) {
    const MachineUi* machine = machineUiFor(job);
    if (!plan || !machine) return;
    cell->setPlan(*machine, plan, job);
    plots->setMachine(*machine); // renames only when the machine changes (it clears the data)
    progress->setPlannedTotals(static_cast<std::uint32_t>(machine->plannedPointCount(*plan)),
                               plan->program ? plan->program->cut_time_s : 0.0);
}

} // namespace CutCell::ui
