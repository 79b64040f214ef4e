#pragma once
// PID gains with first-order filter per joint, and the simulated joint plant.
#include "ui/forms/job_form.h"

namespace CutCell::ui {

class ControllerForm : public JobForm {
    Q_OBJECT
  public:
    explicit ControllerForm(JobEditor* editor, QWidget* parent = nullptr);
};

} // namespace CutCell::ui
