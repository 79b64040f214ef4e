#pragma once
// The quick-return cutter's figures page: the core's cutting experiment (experiment 2,
// quick_return::runCutting, the very control law the engine runs) simulated offline for the
// job's controller: the velocity profile y'(t) against y_d'(t), the phase diagram (y against
// y') and the velocity error y_d' - y' while the tool is in the work, with its max and RMS.
// Built only with the plots library (CUTCELL_HAVE_PLOTS).
#include "ui/forms/job_form.h"

class QLabel;
class QPushButton;

namespace cutcell::plots {
class XyFiguresWidget;
}

namespace CutCell::ui {

class QuickReturnFiguresForm : public JobForm {
    Q_OBJECT
  public:
    explicit QuickReturnFiguresForm(JobEditor* editor, QWidget* parent = nullptr);

    // Simulates the edited job's cut and draws it; false + *why when the job cannot be run.
    bool simulate(QString* why = nullptr);
    cutcell::plots::XyFiguresWidget* figures() const { return figures_; }
    QLabel* summary() const { return summary_; }
    QPushButton* simulateButton() const { return button_; }

  private:
    cutcell::plots::XyFiguresWidget* figures_ = nullptr;
    QLabel* summary_ = nullptr;
    QPushButton* button_ = nullptr;
};

} // namespace CutCell::ui
