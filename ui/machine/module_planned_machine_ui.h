#pragma once
// A MachineUi for a machine whose core module plans the cut itself (MachineModule::plan(): the
// quick-return cutter, next the flying saw and the section-steel line). The module's
// MachinePlan travels in CutPlan::machine_plan; the fields the run controller reads (reachable,
// problem) are set from it. A derived machine adds its title, form pages and scene.
//
// Threading contract: as MachineUi (plan() and the program are pure, any thread).
#include "ui/machine/machine_ui.h"

#include <exception>

namespace cutcell {
class MachineModule;
}

namespace CutCell::ui {

class ModulePlannedMachineUi : public MachineUi {
  public:
    // The core module of this machine's id (throws std::logic_error when none is registered).
    const cutcell::MachineModule& module() const;

    cutcell::Job defaultJob() const override;
    std::vector<ExportKind> exports() const override { return {}; }
    TipErrorPlot tipErrorPlot() const override { return TipErrorPlot::None; }

    cutcell::CutPlan plan(const cutcell::Job& job,
                          const cutcell::PlanOptions& options) const override;
    // The module plan's program with jobText for the run log.
    std::shared_ptr<const cutcell::MotionProgram>
    buildProgram(const cutcell::Job& job, const cutcell::CutPlan& plan,
                 const std::string& jobText) const override;
    std::size_t plannedPointCount(const cutcell::Job& job,
                                  const cutcell::CutPlan& plan) const override;
    QString planSummary(const cutcell::Job& job, const cutcell::CutPlan& plan) const override;

  protected:
    // The common pipe-joint fields (Pipes page: both pipes, angle, eccentricity; the Cut page)
    // each with `why`: for unusedCommonFields() of a machine that cuts no pipe joint.
    static std::vector<std::pair<std::string, QString>> pipeJointFields(const QString& why);
    // *out = build(), or false with the exception's text in *why (a scene builder refuses a
    // job it cannot draw by throwing). Instantiated only where the 3D view is built.
    template <class Build>
    static bool sceneOrWhy(Build build, cutcell::view3d::SceneModel* out, QString* why) {
        try {
            *out = build();
            return true;
        } catch (const std::exception& e) {
            if (why) *why = QString::fromUtf8(e.what());
            return false;
        }
    }
};

} // namespace CutCell::ui
