#pragma once
// The quick-return cutter's own keys (Job::machine_spec, core/machines/quick_return/
// quick_return_spec.h) on two pages: the mechanism (loop dimensions, slider, crank motor, the
// cut and the tracking experiment) and the controller (experiment, control law and the
// parameters of each law). The keys are those of the machine section, as validate() names them.
#include "ui/forms/job_form.h"

class QGroupBox;

namespace CutCell::ui {

class QuickReturnMechanismForm : public JobForm {
    Q_OBJECT
  public:
    explicit QuickReturnMechanismForm(JobEditor* editor, QWidget* parent = nullptr);
};

class QuickReturnControllerForm : public JobForm {
    Q_OBJECT
  public:
    explicit QuickReturnControllerForm(JobEditor* editor, QWidget* parent = nullptr);

  protected:
    // Only the chosen law's parameters are enabled.
    void reloadExtra(const cutcell::Job& job) override;

  private:
    QGroupBox* gains_[4] = {}; // FFC, LQT, SMC, OSMC
};

} // namespace CutCell::ui
