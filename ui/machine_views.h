#pragma once
// Adapts the monitor views to the planned job's machine (MachineUi): the 3D scene, the plots'
// channels (the machine's axis names and units, its tip error plot) and the progress totals.
//
// Threading contract: GUI thread only.
#include "core/job/job.h"
#include "core/machine/machine_module.h"

#include <memory>

namespace CutCell::ui {

class CellViewPanel;
class PlotsPanel;
class ProgressPanel;

void adaptViewsToPlan(const std::shared_ptr<const cutcell::MachinePlan>& plan,
                      const cutcell::Job& job, CellViewPanel* cell, PlotsPanel* plots,
                      ProgressPanel* progress);

} // namespace CutCell::ui
