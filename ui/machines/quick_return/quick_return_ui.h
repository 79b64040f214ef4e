#pragma once
// The quick-return (Whitworth) cutter of seed 004 in the operator station: one crank in torque
// mode under a task-space control law; its core module plans (ModulePlannedMachineUi). Pages:
// the mechanism, the controller, the figures of the cutting experiment (the last run's
// telemetry, live, or an offline simulation) and experiment 1 (all four controllers). 3D: the
// linkage animated from the crank angle. None of the pipe fields apply.
#include "core/machines/quick_return/quick_return_spec.h"
#include "ui/machine/module_planned_machine_ui.h"

namespace CutCell::ui {

class QuickReturnUi : public ModulePlannedMachineUi {
  public:
    // The id is the core module's (one definition per machine).
    static constexpr const char* kId = cutcell::kQuickReturnId;

    std::string id() const override { return kId; }
    QString title() const override;
    std::vector<FormPage> formPages() const override;
    std::vector<std::pair<std::string, QString>> unusedCommonFields() const override;
    bool buildScene(const cutcell::Job& job, const cutcell::MachinePlan& plan,
                    cutcell::view3d::SceneModel* out, QString* why) const override;
};

} // namespace CutCell::ui
