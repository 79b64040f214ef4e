#pragma once
// Control cycle, engine behaviour (stop category, feed hold, limits) and the devices.
#include "ui/forms/job_form.h"

namespace CutCell::ui {

class CycleDevicesForm : public JobForm {
    Q_OBJECT
  public:
    explicit CycleDevicesForm(JobEditor* editor, QWidget* parent = nullptr);
};

} // namespace CutCell::ui
