#pragma once
// The pipe-cutting robot of seed 000 in the operator station: a 5-DOF arm over a rotating pipe
// chuck (six rotary axes). Pages: Method, Robot (DH table with joint limits), Controller (PID
// and joint plant per axis), Compare (both methods side by side: method_comparison_page.h);
// plots: six joint errors in deg and the torch tip's x/y/z error in the robot base frame;
// exports: the wrap-around cutting templates (no G-code: the robot runs joint trajectories, not
// an NC program).
#include "core/machines/pipe_robot/pipe_robot_module.h"
#include "ui/machine/machine_ui.h"

namespace CutCell::ui {

class PipeRobotUi : public MachineUi {
  public:
    // The id is the core module's (one definition per machine).
    static constexpr const char* kId = cutcell::kPipeRobotId;

    std::string id() const override { return kId; }
    QString title() const override;
    cutcell::Job defaultJob() const override;
    std::vector<FormPage> formPages() const override;
    TipErrorPlot tipErrorPlot() const override { return TipErrorPlot::BaseXyz; }
    std::vector<ExportKind> exports() const override;
    // The module's plan; an unreachable path's problem is the planner's sentence (the point,
    // the joint, the limit), which the GUI puts after its own "Path not reachable".
    cutcell::MachinePlan plan(const cutcell::Job& job,
                              const cutcell::PlanOptions& options) const override;
    QString planSummary(const cutcell::Job& job, const cutcell::MachinePlan& plan) const override;
    bool buildScene(const cutcell::Job& job, const cutcell::MachinePlan& plan,
                    cutcell::view3d::SceneModel* out, QString* why) const override;
};

} // namespace CutCell::ui
