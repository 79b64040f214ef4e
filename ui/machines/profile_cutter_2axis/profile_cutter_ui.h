#pragma once
// The 2-axis NC pipe profile cutter of seed 002 in the operator station: the pipe turns in the
// chuck (A, rotary, deg) under a torch on a linear carriage (X, mm), open-loop steppers behind
// a pulse card. Page: Profile cutter (pulses, travel, pierce); the robot's bevel and torch tilt
// do not apply (the torch stands radial). Plots: A in deg, X in mm and the torch's miss on the
// pipe (mm; the tip model's frame turns with the pipe, so no x/y/z). Exports: G-code (X/A) and
// the cutting templates.
#include "ui/machine/machine_ui.h"

namespace CutCell::ui {

class ProfileCutterUi : public MachineUi {
  public:
    static constexpr const char* kId = "profile_cutter_2axis";

    std::string id() const override { return kId; }
    QString title() const override;
    cutcell::Job defaultJob() const override;
    std::vector<FormPage> formPages() const override;
    std::vector<std::pair<std::string, QString>> unusedCommonFields() const override;
    TipErrorPlot tipErrorPlot() const override { return TipErrorPlot::MissOnPipe; }
    std::vector<ExportKind> exports() const override;
    std::string exportText(ExportKind kind, const cutcell::Job& job, QString* what) const override;
    cutcell::CutPlan plan(const cutcell::Job& job,
                          const cutcell::PlanOptions& options) const override;
    std::shared_ptr<const cutcell::MotionProgram>
    buildProgram(const cutcell::Job& job, const cutcell::CutPlan& plan,
                 const std::string& jobText) const override;
    std::size_t plannedPointCount(const cutcell::Job& job,
                                  const cutcell::CutPlan& plan) const override;
    QString planSummary(const cutcell::Job& job, const cutcell::CutPlan& plan) const override;
    bool buildScene(const cutcell::Job& job, const cutcell::CutPlan& plan,
                    cutcell::view3d::SceneModel* out, QString* why) const override;
};

} // namespace CutCell::ui
