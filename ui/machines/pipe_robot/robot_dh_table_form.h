#pragma once
// The robot's Denavit-Hartenberg table with each joint's operating range.
#include "ui/forms/job_form.h"

namespace CutCell::ui {

class RobotDhTableForm : public JobForm {
    Q_OBJECT
  public:
    explicit RobotDhTableForm(JobEditor* editor, QWidget* parent = nullptr);
};

} // namespace CutCell::ui
