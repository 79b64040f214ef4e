#pragma once
// A MachineUi with the defaults of most machines: the core module's default job, no exports of
// its own, no tool-tip plot; and helpers for their unused fields and scenes. A derived machine
// adds its title, form pages and scene.
//
// Threading contract: as MachineUi (plan() and the program are pure, any thread).
#include "ui/machine/machine_ui.h"

#include <exception>

namespace CutCell::ui {

class ModulePlannedMachineUi : public MachineUi {
  public:
    cutcell::Job defaultJob() const override;
    std::vector<ExportKind> exports() const override { return {}; }
    TipErrorPlot tipErrorPlot() const override { return TipErrorPlot::None; }

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
