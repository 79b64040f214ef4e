#pragma once
// The 2-axis NC pipe profile cutter of seed 002 in the operator station: the pipe turns in the
// chuck (A, rotary, deg) under a torch on a linear carriage (X, mm), open-loop steppers behind
// a pulse card. Page: Profile cutter (pulses, travel, pierce); the robot's bevel and torch tilt
// do not apply (the torch stands radial). Plots: A in deg, X in mm and the torch's miss on the
// pipe (mm; the tip model's frame turns with the pipe, so no x/y/z). Exports: G-code (X/A) and
// the cutting templates. The core module plans the cut once; its program is the one that runs.
#include "core/machines/profile_cutter/profile_cutter_module.h"
#include "ui/machine/module_planned_machine_ui.h"

namespace CutCell::ui {

class ProfileCutterUi : public ModulePlannedMachineUi {
  public:
    // The id is the core module's (one definition per machine).
    static constexpr const char* kId = cutcell::kProfileCutterId;

    std::string id() const override { return kId; }
    QString title() const override;
    cutcell::Job defaultJob() const override;
    std::vector<FormPage> formPages() const override;
    std::vector<std::pair<std::string, QString>> unusedCommonFields() const override;
    TipErrorPlot tipErrorPlot() const override { return TipErrorPlot::MissOnPipe; }
    std::vector<ExportKind> exports() const override;
    std::string exportText(ExportKind kind, const cutcell::Job& job, QString* what) const override;
    // Its section's other branches and hole position.
    cutcell::JointExtras jointExtras(const cutcell::Job& job) const override;
    // Planned once, by the core module (ModulePlannedMachineUi: its program runs).
    QString planSummary(const cutcell::Job& job, const cutcell::MachinePlan& plan) const override;
    bool buildScene(const cutcell::Job& job, const cutcell::MachinePlan& plan,
                    cutcell::view3d::SceneModel* out, QString* why) const override;
};

} // namespace CutCell::ui
