#pragma once
// The cutting method (static pipe or rotating pipe) and its chuck settings.
#include "ui/forms/job_form.h"

namespace CutCell::ui {

class MethodForm : public JobForm {
    Q_OBJECT
  public:
    explicit MethodForm(JobEditor* editor, QWidget* parent = nullptr);
};

} // namespace CutCell::ui
