#pragma once
// The consumables of the torch (issue 24): what the set named by the job's cut chart has done
// since it was fitted - cuts, pierces, arc-on time, cut length - against the life its chart
// expects, with a warning from 90 % and an alarm from 100 % of the limit used most; its earlier
// installations; and "New consumables fitted", which starts the set from zero (the ledger keeps
// the old counts and writes the audit trail). Reads and writes through core's ConsumableLedger
// (devices/record/ answers, the app wires it).
//
// Threading contract: GUI thread only. The ledger's calls are short database statements.
#include "core/process/consumable_counters.h"

#include <QWidget>

#include <functional>
#include <optional>

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTimer;

namespace CutCell::ui {

class JobEditor;

class ConsumablesPanel : public QWidget {
    Q_OBJECT
  public:
    // ledger: null for a station without a record (the panel says so). user: who is logged in.
    ConsumablesPanel(cutcell::ConsumableLedger* ledger, JobEditor* editor,
                     std::function<QString()> user, QWidget* parent = nullptr);

    void refresh();
    // The replacement with its reason (the button asks for it); false with why when refused.
    bool replaceConsumables(const QString& reason, QString* why);
    // The wear shown now (the tests read it).
    const cutcell::ConsumableWear& wear() const { return wear_; }
    QString summary() const;

  protected:
    void showEvent(QShowEvent* e) override;

  private:
    std::optional<cutcell::ConsumableSetId> jobSet() const;
    cutcell::ConsumableLife jobLife() const;

    cutcell::ConsumableLedger* ledger_;
    JobEditor* editor_;
    std::function<QString()> user_;
    QLabel* set_;
    QLabel* counts_;
    QProgressBar* wearBar_;
    QLabel* wearText_;
    QLabel* totals_;
    QTableWidget* history_;
    QPushButton* replace_;
    QLabel* message_;
    QTimer* poll_;
    cutcell::ConsumableWear wear_;
};

} // namespace CutCell::ui
