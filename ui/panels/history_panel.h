#pragma once
// The production record read back at the station (issue 25's History view): the runs filtered
// by machine, job, outcome and day; a run's details (what it made, where it stopped, its
// alarms); the cycle time per run and the alarm Pareto of the runs shown; the shift report of
// the runs shown as CSV or PDF. Reads through core's RunHistory (devices/record/ answers, the
// app wires it); refreshed on request and after each run.
//
// Threading contract: GUI thread only.
#include "core/record/run_record.h"

#include <QDate>
#include <QWidget>

#include <vector>

class QComboBox;
class QShowEvent;
class QDateEdit;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QTableWidget;

namespace cutcell::plots {
class HistoryChartsWidget;
}

namespace CutCell::ui {

class HistoryPanel : public QWidget {
    Q_OBJECT
  public:
    // history outlives the panel (null: a station without a record; the panel says so).
    explicit HistoryPanel(const cutcell::RunHistory* history, QWidget* parent = nullptr);

    void refresh();
    // The runs shown now (the filters applied), oldest first.
    const std::vector<cutcell::RecordedRun>& shown() const { return shown_; }
    void setSince(const QDate& day);
    void setMachineFilter(const QString& machineId); // "" for every machine
    void setJobFilter(const QString& text);
    void setOutcomeFilter(const QString& outcome); // "" for every outcome
    // The shift report of the runs shown: CSV (one line per run, then the totals) or PDF.
    // False with the reason when the file cannot be written.
    bool writeCsv(const QString& path, QString* why) const;
    bool writePdf(const QString& path, QString* why) const;
    void selectRun(int row);
    QString details() const;
#ifdef CUTCELL_HAVE_PLOTS
    cutcell::plots::HistoryChartsWidget* charts() const {
        return charts_;
    }
#endif

    // An alarm's text as the Pareto counts it: measured figures (numbers with a decimal point
    // or of 3 digits and more) as "#", so one kind of alarm is one bar; axis and node numbers
    // stay.
    static QString alarmKind(const QString& text);

  protected:
    void showEvent(QShowEvent* e) override; // each look at the tab reads the record again

  private:
    void showDetails();
    QString reportText() const;

    const cutcell::RunHistory* history_;
    QComboBox* machine_;
    QLineEdit* job_;
    QComboBox* outcome_;
    QDateEdit* since_;
    QTableWidget* table_;
    QPlainTextEdit* details_;
    QLabel* summary_;
#ifdef CUTCELL_HAVE_PLOTS
    cutcell::plots::HistoryChartsWidget* charts_ = nullptr;
#endif
    std::vector<cutcell::RecordedRun> shown_;
};

} // namespace CutCell::ui
