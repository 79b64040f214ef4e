#pragma once
// The job's identity, common to every machine: its name and description.
#include "ui/forms/job_form.h"

namespace CutCell::ui {

class JobInfoForm : public JobForm {
    Q_OBJECT
  public:
    explicit JobInfoForm(JobEditor* editor, QWidget* parent = nullptr);
};

} // namespace CutCell::ui
