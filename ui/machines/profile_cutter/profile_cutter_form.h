#pragma once
// The 2-axis NC pipe profile cutter's own keys (seed 002): A-axis grid and pulses, X-axis
// resolution, the pulse card's rate limit, the pierce dwell, the X travel and the hole's
// branch position. The page of this machine (ProfileCutterUi::formPages).
#include "ui/forms/job_form.h"

class QCheckBox;
class QDoubleSpinBox;

namespace CutCell::ui {

class ProfileCutterForm : public JobForm {
    Q_OBJECT
  public:
    explicit ProfileCutterForm(JobEditor* editor, QWidget* parent = nullptr);

  protected:
    void reloadExtra(const cutcell::Job& job) override;

  private:
    QCheckBox* autoPosition_ = nullptr;
    QDoubleSpinBox* position_ = nullptr;
};

} // namespace CutCell::ui
