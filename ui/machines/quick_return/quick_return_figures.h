#pragma once
// The quick-return cutter's "Cut figures" page (experiment 2 of seed 004): the velocity
// profile y'(t) against y_d'(t), the phase diagram (y' against y) and the velocity error
// y_d' - y' while the tool is in the work, with its max and RMS, from one of two sources:
//   - the last run on the engine (live while it runs): its telemetry, read by
//     quick_return::RunFigures (core) from the same EngineBridge::samples batches that feed the
//     main window's tracking plots (MainWindow::onSamples); redrawn at most every
//     kLiveRedrawMs while the page is visible, and once when the run ends;
//   - an offline simulation of the job's cut (quick_return::runCutting, the very control law
//     the engine runs) on a pool thread (QtConcurrent): the GUI thread never waits for it.
// The page finds the window's RunController when it is placed in the window (the parameter
// tabs are built inside MainWindow); without one (a bare form) only the simulation works.
// Built only with the plots library (CUTCELL_HAVE_PLOTS).
//
// Threading contract: GUI thread only; the simulation gets a copy of the set-up.
#include "core/machines/quick_return/experiments.h"
#include "core/machines/quick_return/run_figures.h"
#include "ui/forms/job_form.h"

#include <QElapsedTimer>
#include <QFutureWatcher>

#include <memory>
#include <vector>

class QLabel;
class QPushButton;

namespace cutcell::plots {
class XyFiguresWidget;
}

namespace CutCell::ui {

class RunController;

class QuickReturnFiguresForm : public JobForm {
    Q_OBJECT
  public:
    static constexpr int kLiveRedrawMs = 500;
    enum class Source { None, LastRun, Simulation };

    explicit QuickReturnFiguresForm(JobEditor* editor, QWidget* parent = nullptr);
    ~QuickReturnFiguresForm() override;

    // Starts the offline simulation of the edited job's cut; false + *why when the job cannot
    // be simulated or one is running. simulated() follows on the GUI thread.
    bool startSimulation(QString* why = nullptr);
    bool simulating() const;
    // Feeds one batch of telemetry (connected to the window's EngineBridge::samples; tests).
    void addSamples(const std::vector<cutcell::TelemetrySample>& batch);
    // Draws what the source has now (the live redraw does this throttled).
    void redraw();

    Source source() const { return source_; }
    const cutcell::quick_return::RunFigures& runFigures() const { return run_; }
    RunController* runController() const { return runController_; }
    cutcell::plots::XyFiguresWidget* figures() const { return figures_; }
    QLabel* summary() const { return summary_; }
    QLabel* sourceLabel() const { return sourceLabel_; }
    QPushButton* simulateButton() const { return button_; }
    int redraws() const { return redraws_; }

  signals:
    void simulated(bool completed);
    void runFiguresDrawn(); // after a redraw of the last run's figures

  protected:
    bool event(QEvent* e) override;
    void showEvent(QShowEvent* e) override;

  private:
    void attachToWindow();
    void simulationFinished();
    // The three panels from points (in_work marks the error's samples).
    void draw(const std::vector<cutcell::quick_return::RunFigurePoint>& points);

    cutcell::plots::XyFiguresWidget* figures_ = nullptr;
    QLabel* sourceLabel_ = nullptr;
    QLabel* summary_ = nullptr;
    QPushButton* button_ = nullptr;
    RunController* runController_ = nullptr;

    Source source_ = Source::None;
    cutcell::quick_return::RunFigures run_;
    bool dirty_ = false;
    QElapsedTimer sinceDraw_;
    int redraws_ = 0;

    QFutureWatcher<cutcell::quick_return::CuttingResult>* watcher_ = nullptr;
    cutcell::quick_return::ExperimentSetup simSetup_;
    QString simController_;
};

} // namespace CutCell::ui
