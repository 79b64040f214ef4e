#pragma once
// The two pipes of a pipe joint: main (run) pipe, branch pipe, their angle and eccentricity.
#include "ui/forms/job_form.h"

namespace CutCell::ui {

class PipesForm : public JobForm {
    Q_OBJECT
  public:
    explicit PipesForm(JobEditor* editor, QWidget* parent = nullptr);
};

} // namespace CutCell::ui
