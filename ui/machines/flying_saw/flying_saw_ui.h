#pragma once
// The flying saw of seed 003 in the operator station: a carriage synchronised to a welded-pipe
// line (measured by a roller encoder), a turntable with two blades on radial feeds; its core
// module plans (ModulePlannedMachineUi). Pages: the tube, the line and the queue of lengths; the
// carriage and the saw; the cycle and cut figures (carriage s, v, a with the periods, the cam
// table, the cut length of every piece of the queue's simulation, the cam table CSV export).
// 3D: the pipe moving through the cell, the carriage riding with it, the turntable turning its
// blades on their radial feeds. None of the pipe-robot fields apply.
#include "ui/machine/module_planned_machine_ui.h"

namespace CutCell::ui {

class FlyingSawUi : public ModulePlannedMachineUi {
  public:
    std::string id() const override;
    QString title() const override;
    std::vector<FormPage> formPages() const override;
    std::vector<std::pair<std::string, QString>> unusedCommonFields() const override;
    bool buildScene(const cutcell::Job& job, const cutcell::MachinePlan& plan,
                    cutcell::view3d::SceneModel* out, QString* why) const override;
};

} // namespace CutCell::ui
