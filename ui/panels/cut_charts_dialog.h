#pragma once
// "Cut charts…": the cut-chart library in use (core/process/cut_chart_library.h: the user's
// table when it exists, else the shipped one) as a table per process, material and consumable
// set - a row per thickness, a column per figure - with editable cells, Add row, Remove row
// and Save. Every edit goes through core's edits, which check as the reader checks; a refusal
// is shown under the table with the checker's message (chart, row, field, value, unit, limit)
// and the cell keeps its old value. Save writes the user's table atomically and installs it as
// the active library (the job's forms show the new figures). Numbers are shown in the GUI
// language's form and typed with '.' or ',' as the forms take them (ui/forms/number_fields.h).
// Only the setter level and above may edit (no access control, or single-user mode: anyone);
// below it the dialog is read-only and says why.
//
// Threading contract: GUI thread only.
#include "core/process/cut_chart.h"

#include <QDialog>
#include <QPointer>
#include <QString>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;
class QTableWidgetItem;

namespace CutCell::ui {

class AccessControl;

// "" when the cut charts may be edited now, else why not (the level it needs, who is logged in).
QString cutChartsLockReason(const AccessControl* access);

// Installs the table in use under `dataHome` (the user's, when its file exists) as the active
// library (core/process/process_spec.h), once per program: later calls return the first
// answer. "" when done, else the problem (an unreadable user's table: the shipped one stays).
QString installCutChartsInUse(const std::string& dataHome);

class CutChartsDialog : public QDialog {
    Q_OBJECT
  public:
    // dataHome: where the user's table lives (cutcell::defaultDataHome()); access: null when the
    // station has no user levels.
    CutChartsDialog(std::string dataHome, AccessControl* access, QWidget* parent = nullptr);

    const cutcell::CutChartSet& table() const { return table_; }
    const std::string& userPath() const { return path_; }
    bool modified() const { return modified_; }
    // "" when the table may be edited here, else why not.
    QString lockReason() const;
    // The message of the last refusal ("" after an edit that was taken).
    QString problem() const;
    QTableWidget* rowTable() const { return rows_; }
    // Shows a chart; false (and nothing changes) when the table has no such chart.
    bool showChart(cutcell::CutProcess p, const std::string& material,
                   const std::string& consumable);
    // Writes the table to the user's file and installs it; false with the reason shown.
    bool save();
    void addRow();    // after the selected row (the last when none is selected)
    void removeRow(); // the selected row

  signals:
    void saved();

  public slots:
    void reject() override; // Close: unsaved edits are saved, discarded or kept on request

  private:
    void fillMaterials();
    void fillConsumables();
    void showRows();
    void applyAccess();
    void cellEdited(QTableWidgetItem* item);
    void setProblem(const QString& text);
    void took(const std::string& key, const QString& was, const QString& now, const QString& unit);
    std::optional<std::size_t> chartIndex() const;

    std::string dataHome_, path_;
    QPointer<AccessControl> access_;
    cutcell::CutChartSet table_;
    QString loadProblem_;
    bool modified_ = false;
    bool filling_ = false;
    struct Change {
        std::string key;
        QString was, now, unit;
    };
    std::vector<Change> changes_; // since the last save, for the audit trail

    QLabel* where_;
    QLabel* lock_;
    QComboBox* process_;
    QComboBox* material_;
    QComboBox* consumable_;
    QTableWidget* rows_;
    QLabel* problem_;
    QLabel* status_;
    QPushButton* add_;
    QPushButton* remove_;
    QPushButton* save_;
    QPushButton* close_;
};

} // namespace CutCell::ui
