#pragma once
// The section-steel cutting cell of seed 001 in the operator station: a 3R path arm and a
// 5-DOF groove arm cutting the end of an I/H, channel or angle section square or mitred, with
// V, Y or K weld-preparation grooves; its core module plans (ModulePlannedMachineUi). Pages:
// the section (catalogue or user-defined) and its length, the end cut, the motion, the arms,
// the drives. 3D: the extruded section, both arms and the torch path. None of the pipe fields
// apply.
#include "core/machines/section_steel/section_steel_module.h"
#include "ui/machine/module_planned_machine_ui.h"

namespace CutCell::ui {

class SectionSteelUi : public ModulePlannedMachineUi {
  public:
    // The id is the core module's (one definition per machine).
    static constexpr const char* kId = cutcell::kSectionSteelId;

    std::string id() const override { return kId; }
    QString title() const override;
    std::vector<FormPage> formPages() const override;
    std::vector<std::pair<std::string, QString>> unusedCommonFields() const override;
    bool buildScene(const cutcell::Job& job, const cutcell::MachinePlan& plan,
                    cutcell::view3d::SceneModel* out, QString* why) const override;
};

} // namespace CutCell::ui
