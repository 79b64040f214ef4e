#include "ui/machine_views.h"

#include "ui/machine_plan.h"
#include "ui/panels/monitor_views.h"
#include "ui/panels/progress_panel.h"

#include <QStringList>
#include <QVariant>

namespace CutCell::ui {

void adaptViewsToPlan(const std::shared_ptr<const cutcell::CutPlan>& plan, const cutcell::Job& job,
                      CellViewPanel* cell, PlotsPanel* plots, ProgressPanel* progress) {
    if (!plan) return;
    cell->setPlan(plan, job);
    // Axis names only when the machine changes: renaming clears the plots' data.
    const QString machine = QString::fromStdString(job.machine);
    if (plots->property("cutcellMachine").toString() != machine) {
        plots->setProperty("cutcellMachine", machine);
        std::array<bool, cutcell::kAxisCount> linear{};
        if (isProfileCutterJob(job)) {
            linear[1] = true;
            plots->setAxisNames({QObject::tr("A chuck (deg)"), QObject::tr("X carriage (mm)")});
        } else {
            plots->setAxisNames(
                {"q0 chuck", "q1 base", "q2 shoulder", "q3 elbow", "q4 wrist", "q5 roll"});
        }
        plots->setLinearAxes(linear);
    }
    progress->setPlannedTotals(static_cast<std::uint32_t>(plannedPointCount(job, *plan)),
                               plan->cut_time_s);
}

} // namespace CutCell::ui
