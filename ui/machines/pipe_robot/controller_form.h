#pragma once
// The robot's drives: PID gains with first-order filter per joint (and their SIMC tuning from
// the model, "Tune (SIMC)"), the mechanics the simulated drives run - the plant model (rigid
// body or linear), gravity feed-forward, the linear joint plants, the arm's links, the drive
// trains and the chuck.
//
// Threading contract: GUI thread; the tuning (it plans the cut) runs on the thread pool.
#include "ui/forms/job_form.h"

#include <atomic>
#include <memory>

class QLabel;
class QPushButton;

namespace CutCell::ui {

class ControllerForm : public JobForm {
    Q_OBJECT
  public:
    explicit ControllerForm(JobEditor* editor, QWidget* parent = nullptr);
    ~ControllerForm() override;

  private:
    // SIMC gains for the six axes from the edited job; written into the PID table as edits.
    void tune();

    QPushButton* tuneButton_ = nullptr;
    QLabel* tuneStatus_ = nullptr;
    // The job's edits and resets so far: a tuning of an older job is not applied.
    quint64 generation_ = 0;
    std::shared_ptr<std::atomic<bool>> cancel_;
};

} // namespace CutCell::ui
