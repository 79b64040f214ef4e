#pragma once
// The quick-return cutter's "Experiment 1" page (seed 004): tracking
// y_d = offset + amplitude sin(omega t) without contact force for all four controllers (FFC,
// LQT, SMC, OSMC) with the job's parameters, by the core's quick_return::runTracking (the
// engine's control law on the crank plant). Shows the table of the MSE of L e over the last
// mse_window seconds (the job's L and window; seed: L = 100, 2 s), max |e| there and the peak
// torque, and per controller a plot of y and y_d over time, with the four errors e = y_d - y
// in one more plot. The four runs go to a pool thread (QtConcurrent): the GUI thread never
// waits; the numbers are written in the C locale (decimal point) under any locale.
// Built only with the plots library (CUTCELL_HAVE_PLOTS).
//
// Threading contract: GUI thread only; the pool thread gets a copy of the set-up.
#include "core/machines/quick_return/experiments.h"
#include "ui/forms/job_form.h"

#include <QFutureWatcher>

#include <atomic>
#include <memory>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace cutcell::plots {
class XyFiguresWidget;
}

namespace CutCell::ui {

// The four tracking runs of one request.
struct TrackingBatch {
    std::vector<cutcell::quick_return::TrackingResult> results; // FFC, LQT, SMC, OSMC
    bool cancelled = false;
    bool offGuiThread = false; // where the runs were computed (checked by the GUI test)
    double seconds = 0;        // wall time of the four runs
};

class QuickReturnTrackingForm : public JobForm {
    Q_OBJECT
  public:
    explicit QuickReturnTrackingForm(JobEditor* editor, QWidget* parent = nullptr);
    ~QuickReturnTrackingForm() override;

    // Starts experiment 1 for the edited job; false + *why when the job cannot be simulated
    // or a run is in flight. finished() follows on the GUI thread.
    bool startExperiment(QString* why = nullptr);
    bool running() const;
    const TrackingBatch& lastBatch() const { return last_; }
    // The set-up of the last request (the job's parameters then).
    const cutcell::quick_return::ExperimentSetup& lastSetup() const { return setup_; }

    QTableWidget* table() const { return table_; }
    cutcell::plots::XyFiguresWidget* figures() const { return figures_; }
    QLabel* status() const { return status_; }
    QPushButton* runButton() const { return button_; }

  signals:
    void finished();

  protected:
    void reloadExtra(const cutcell::Job& job) override;

  private:
    void fitTableHeight();
    void batchFinished();
    void describe(const cutcell::Job& job);

    QLabel* intro_ = nullptr;
    QPushButton* button_ = nullptr;
    QLabel* status_ = nullptr;
    QTableWidget* table_ = nullptr;
    cutcell::plots::XyFiguresWidget* figures_ = nullptr;
    QFutureWatcher<TrackingBatch>* watcher_ = nullptr;
    std::shared_ptr<std::atomic<bool>> cancel_;
    cutcell::quick_return::ExperimentSetup setup_;
    TrackingBatch last_;
};

} // namespace CutCell::ui
