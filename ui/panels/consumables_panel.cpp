#include "ui/panels/consumables_panel.h"

#include "core/process/process_spec.h"
#include "ui/forms/job_editor.h"

#include <QDateTime>
#include <QGridLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <exception>

namespace CutCell::ui {

namespace {

QString when(std::int64_t ms) {
    if (ms <= 0) return QStringLiteral("-");
    return QLocale().toString(QDateTime::fromMSecsSinceEpoch(ms), QLocale::ShortFormat);
}

QString minutes(std::int64_t arcMs) {
    return QLocale().toString(static_cast<double>(arcMs) / 60000.0, 'f', 1);
}

} // namespace

ConsumablesPanel::ConsumablesPanel(cutcell::ConsumableLedger* ledger, JobEditor* editor,
                                   std::function<QString()> user, QWidget* parent)
    : QWidget(parent), ledger_(ledger), editor_(editor), user_(std::move(user)),
      set_(new QLabel(this)), counts_(new QLabel(this)), wearBar_(new QProgressBar(this)),
      wearText_(new QLabel(this)), totals_(new QLabel(this)), history_(new QTableWidget(this)),
      replace_(new QPushButton(tr("New consumables fitted..."), this)), message_(new QLabel(this)),
      poll_(new QTimer(this)) {
    setObjectName("consumablesPanel");
    auto* v = new QVBoxLayout(this);
    set_->setObjectName("consumableSet");
    set_->setWordWrap(true);
    v->addWidget(set_);
    counts_->setObjectName("consumableCounts");
    v->addWidget(counts_);
    wearBar_->setObjectName("consumableWear");
    wearBar_->setRange(0, 100);
    wearBar_->setTextVisible(true);
    v->addWidget(wearBar_);
    wearText_->setObjectName("consumableWearText");
    wearText_->setWordWrap(true);
    v->addWidget(wearText_);
    history_->setObjectName("consumableHistory");
    history_->setColumnCount(7);
    history_->setHorizontalHeaderLabels({tr("Fitted"), tr("Removed"), tr("Cuts"), tr("Pierces"),
                                         tr("Arc-on [min]"), tr("Cut length [m]"),
                                         tr("Removed by, why")});
    history_->verticalHeader()->hide();
    history_->setTabKeyNavigation(false);
    history_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    history_->horizontalHeader()->setStretchLastSection(true);
    v->addWidget(history_, 1);
    totals_->setObjectName("consumableTotals");
    v->addWidget(totals_);
    replace_->setObjectName("consumablesReplace");
    v->addWidget(replace_, 0, Qt::AlignLeft);
    message_->setObjectName("consumableMessage");
    message_->setWordWrap(true);
    v->addWidget(message_);

    connect(replace_, &QPushButton::clicked, this, [this] {
        bool ok = false;
        const QString reason = QInputDialog::getText(
            this, tr("New consumables fitted"),
            tr("Why were they changed (worn nozzle, electrode pit depth, cut quality)?"),
            QLineEdit::Normal, {}, &ok);
        if (!ok) return;
        QString why;
        if (!replaceConsumables(reason, &why)) message_->setText(why);
    });
    // The counts grow on the engine's logger thread: shown again every 2 s while visible.
    poll_->setInterval(2000);
    connect(poll_, &QTimer::timeout, this, [this] {
        if (isVisible()) refresh();
    });
    poll_->start();
    if (editor_) {
        connect(editor_, &JobEditor::jobReset, this, &ConsumablesPanel::refresh);
        connect(editor_, &JobEditor::edited, this, &ConsumablesPanel::refresh);
    }
    refresh();
}

void ConsumablesPanel::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    refresh();
}

std::optional<cutcell::ConsumableSetId> ConsumablesPanel::jobSet() const {
    if (!editor_ || !editor_->job().process.used) return std::nullopt;
    const auto& p = editor_->job().process;
    return cutcell::ConsumableSetId{p.process, p.consumable};
}

cutcell::ConsumableLife ConsumablesPanel::jobLife() const {
    if (!editor_) return {};
    const auto& p = editor_->job().process;
    const cutcell::CutChart* chart =
        cutcell::activeCutCharts().find(p.process, p.material, p.consumable);
    return chart ? cutcell::consumableLifeOf(*chart) : cutcell::ConsumableLife{};
}

void ConsumablesPanel::refresh() {
    wear_ = {};
    const auto set = jobSet();
    replace_->setEnabled(ledger_ && set);
    history_->setRowCount(0);
    wearBar_->setValue(0);
    wearBar_->setStyleSheet({});
    if (!ledger_) {
        set_->setText(tr("No production record: consumables are not counted (--record off, or "
                         "the record could not be opened)."));
        counts_->clear();
        wearText_->clear();
        totals_->clear();
        return;
    }
    if (!set) {
        set_->setText(tr("The job cuts without a cut chart (Cut page): no consumable set to "
                         "count."));
        counts_->clear();
        wearText_->clear();
    }
    try {
        if (set) {
            const cutcell::ConsumableCounters c = ledger_->current(*set);
            set_->setText(tr("Consumable set: %1 (fitted %2)")
                              .arg(QString::fromStdString(set->name()), when(c.installed_ms)));
            counts_->setText(tr("%1 cuts, %2 pierces, arc-on %3 min, cut length %4 m")
                                 .arg(c.cuts)
                                 .arg(c.pierces)
                                 .arg(minutes(c.arc_on_ms),
                                      QLocale().toString(c.cut_length_mm / 1000.0, 'f', 2)));
            wear_ = cutcell::consumableWear(c, jobLife());
            wearBar_->setValue(static_cast<int>(std::min(100.0, 100.0 * wear_.fraction)));
            wearBar_->setStyleSheet(wear_.level == cutcell::WearLevel::Alarm
                                        ? "QProgressBar::chunk{background:#c62828}"
                                    : wear_.level == cutcell::WearLevel::Warning
                                        ? "QProgressBar::chunk{background:#f9a825}"
                                        : QString());
            QString text = QString::fromStdString(wear_.text);
            if (wear_.level == cutcell::WearLevel::Alarm)
                text = tr("ALARM: expected life reached, change the consumables (%1)").arg(text);
            else if (wear_.level == cutcell::WearLevel::Warning)
                text = tr("Warning: 90 % of the expected life used (%1)").arg(text);
            wearText_->setText(text);
            const auto rows = ledger_->history(*set);
            history_->setRowCount(static_cast<int>(rows.size()));
            for (size_t i = 0; i < rows.size(); ++i) {
                const auto& h = rows[rows.size() - 1 - i]; // newest first
                const QStringList cells{
                    when(h.installed_ms),
                    h.removed_ms ? when(h.removed_ms) : tr("in the torch"),
                    QString::number(h.cuts),
                    QString::number(h.pierces),
                    minutes(h.arc_on_ms),
                    QLocale().toString(h.cut_length_mm / 1000.0, 'f', 2),
                    h.removed_ms ? QString::fromStdString(h.removed_by + ": " + h.removal_reason)
                                 : QString()};
                for (int col = 0; col < cells.size(); ++col)
                    history_->setItem(static_cast<int>(i), col, new QTableWidgetItem(cells[col]));
            }
        }
        const cutcell::ConsumableTotals t = ledger_->totals();
        totals_->setText(
            tr("All sets: %1 installations, %2 cuts, %3 pierces, arc-on %4 min, %5 m")
                .arg(t.sets)
                .arg(t.cuts)
                .arg(t.pierces)
                .arg(minutes(t.arc_on_ms), QLocale().toString(t.cut_length_mm / 1000.0, 'f', 2)));
        message_->clear();
    } catch (const std::exception& e) {
        message_->setText(tr("The consumable statistics cannot be read: %1").arg(e.what()));
    }
}

bool ConsumablesPanel::replaceConsumables(const QString& reason, QString* why) {
    const auto set = jobSet();
    if (!ledger_ || !set) {
        if (why) *why = tr("No consumable set to replace (no record, or no cut chart in the job).");
        return false;
    }
    if (reason.trimmed().isEmpty()) {
        if (why) *why = tr("Say why the consumables were changed: the record keeps it.");
        return false;
    }
    try {
        const QString who = user_ ? user_() : QString();
        ledger_->replace(*set, (who.isEmpty() ? QStringLiteral("operator") : who).toStdString(),
                         reason.trimmed().toStdString());
    } catch (const std::exception& e) {
        if (why) *why = tr("Not recorded: %1").arg(e.what());
        return false;
    }
    refresh();
    message_->setText(tr("New consumables recorded: the counts start from zero."));
    return true;
}

QString ConsumablesPanel::summary() const {
    return set_->text() + QLatin1Char('\n') + counts_->text() + QLatin1Char('\n') +
           wearText_->text();
}

} // namespace CutCell::ui
