#pragma once
// The cut: which pipe is cut, bevel, speed and how the path is sampled.
#include "ui/forms/job_form.h"

namespace CutCell::ui {

class CutForm : public JobForm {
    Q_OBJECT
  public:
    explicit CutForm(JobEditor* editor, QWidget* parent = nullptr);
};

} // namespace CutCell::ui
