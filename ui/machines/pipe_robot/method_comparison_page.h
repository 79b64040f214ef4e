#pragma once
// The robot's "Compare" page (seed 000, Section 4, Fig. 11-14): the edited job's cut with the
// pipe static and with the pipe turning, planned and simulated offline
// (runMethodComparison, the plant of `cutcell-cli simulate`): the table of both methods' max
// |joint error|, tip error range and the rotating/static ratios, and two figures of the method
// chosen in the selector - joint errors (Fig. 11 / 12) and the torch tip's x/y/z error (Fig.
// 13 / 14) over time. `cutcell-cli compare` writes the same as files.
// The comparison runs on a pool thread (QtConcurrent): the GUI thread never waits for it; a
// page destroyed meanwhile cancels the plans and waits for the run to end.
// Built only with the plots library (CUTCELL_HAVE_PLOTS).
//
// Threading contract: GUI thread only; the comparison gets a copy of the job.
#include "core/machines/pipe_robot/method_comparison.h"
#include "ui/forms/job_form.h"

#include <QFutureWatcher>

#include <atomic>
#include <memory>
#include <optional>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace cutcell::plots {
class XyFiguresWidget;
}

namespace CutCell::ui {

class MethodComparisonForm : public JobForm {
    Q_OBJECT
  public:
    explicit MethodComparisonForm(JobEditor* editor, QWidget* parent = nullptr);
    ~MethodComparisonForm() override;

    // Starts the comparison of the edited job; false + *why when one is running.
    // compared() follows on the GUI thread.
    bool startComparison(QString* why = nullptr);
    bool comparing() const;
    // The last comparison (none before the first has ended).
    const std::optional<cutcell::MethodComparison>& result() const { return result_; }

    QPushButton* compareButton() const { return button_; }
    // Which method the figures show: 0 static pipe, 1 rotating pipe.
    QComboBox* methodChoice() const { return method_; }
    QTableWidget* table() const { return table_; }
    cutcell::plots::XyFiguresWidget* figures() const { return figures_; }
    QLabel* summary() const { return summary_; }

  signals:
    void compared(bool ok);

  private:
    void finished();
    void fillTable(const cutcell::MethodComparison& c);
    void fitTableHeight();
    void draw(); // the chosen method's figures of the last comparison

    QPushButton* button_ = nullptr;
    QLabel* summary_ = nullptr;
    QTableWidget* table_ = nullptr;
    QComboBox* method_ = nullptr;
    cutcell::plots::XyFiguresWidget* figures_ = nullptr;
    QFutureWatcher<cutcell::MethodComparison>* watcher_ = nullptr;
    std::shared_ptr<std::atomic<bool>> cancel_;
    std::optional<cutcell::MethodComparison> result_;
};

} // namespace CutCell::ui
