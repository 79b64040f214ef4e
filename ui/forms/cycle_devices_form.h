#pragma once
// Control cycle, engine behaviour (stop category, feed hold, limits) and the devices.
#include "ui/forms/job_form.h"

#include <array>
#include <vector>

namespace CutCell::ui {

class CycleDevicesForm : public JobForm {
    Q_OBJECT
  public:
    explicit CycleDevicesForm(JobEditor* editor, QWidget* parent = nullptr);

  protected:
    void reloadExtra(const cutcell::Job& job) override;

  private:
    std::vector<std::array<QWidget*, 3>> axisRows_; // label, node id, counts per unit
};

} // namespace CutCell::ui
