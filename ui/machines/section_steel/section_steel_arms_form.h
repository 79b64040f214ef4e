#pragma once
// The section-steel cutter's motion, arms and drives pages: cutting speed and its ramps, the
// spline's knot spacing, the torch's turn at the toes, the bevel blend, the torch length; each
// arm's base, the path arm's link lengths, every joint's limits and park position; the PID and
// plant of each of the 8 simulated drives. Keys as validate() names them.
#include "ui/forms/job_form.h"

namespace CutCell::ui {

class SectionSteelArmsForm : public JobForm {
    Q_OBJECT
  public:
    explicit SectionSteelArmsForm(JobEditor* editor, QWidget* parent = nullptr);
};

class SectionSteelDrivesForm : public JobForm {
    Q_OBJECT
  public:
    explicit SectionSteelDrivesForm(JobEditor* editor, QWidget* parent = nullptr);
};

} // namespace CutCell::ui
