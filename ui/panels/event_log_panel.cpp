#include "ui/panels/event_log_panel.h"
#include "ui/panels/engine_text.h"

#include "ui/panels/run_words.h"

#include <QHeaderView>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cstring>

namespace CutCell::ui {

using cutcell::EngineState;
using cutcell::Severity;

EventLogPanel::EventLogPanel(QWidget* parent)
    : QWidget(parent), table_(new QTableWidget(0, 3, this)) {
    table_->setTabKeyNavigation(false); // Tab leaves the table (it walked its cells for ever)
    setObjectName("eventLog");
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    table_->setHorizontalHeaderLabels({tr("Time"), tr("Severity"), tr("Message")});
    // Fixed widths: ResizeToContents would measure every row at each insert.
    const QFontMetrics fm(table_->font());
    table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Fixed);
    table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Fixed);
    table_->setColumnWidth(0, fm.horizontalAdvance(QStringLiteral("00:00:00.000")) + 24);
    table_->setColumnWidth(1, fm.horizontalAdvance(QStringLiteral("WARNING")) + 24);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->verticalHeader()->hide();
    table_->verticalHeader()->setDefaultSectionSize(24);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setWordWrap(false);
    table_->setAlternatingRowColors(true);
    v->addWidget(table_);
}

QString EventLogPanel::clearHint(EngineState to) {
    switch (to) {
    case EngineState::EmergencyStop:
        return tr("To clear: remove the hazard, release the E-STOP, press Reset, then Enable.");
    case EngineState::Fault:
        return tr("To clear: correct the cause named above, press Reset, then Enable and Home.");
    default:
        return {};
    }
}

void EventLogPanel::add(Severity severity, const QString& message, const QDateTime& when) {
    if (table_->rowCount() >= kMaxRows) table_->removeRow(0);
    const int row = table_->rowCount();
    table_->insertRow(row);
    const QString sev = severity == Severity::Error     ? tr("ERROR")
                        : severity == Severity::Warning ? tr("WARNING")
                                                        : tr("info");
    auto* t = new QTableWidgetItem(when.toString(QStringLiteral("HH:mm:ss.zzz")));
    auto* s = new QTableWidgetItem(sev);
    auto* m = new QTableWidgetItem(message);
    m->setToolTip(message);
    const QColor color = severity == Severity::Error     ? QColor(255, 95, 85)
                         : severity == Severity::Warning ? QColor(255, 200, 60)
                                                         : QColor();
    if (color.isValid())
        for (auto* it : {t, s, m})
            it->setForeground(color);
    table_->setItem(row, 0, t);
    table_->setItem(row, 1, s);
    table_->setItem(row, 2, m);
    table_->scrollToBottom();
    emit added(severity, message);
}

void EventLogPanel::addEngineEvent(const cutcell::EngineEvent& e) {
    const auto len = strnlen(e.text.data(), e.text.size());
    // In the GUI's language (the log file keeps core's English).
    QString msg = engineText(QString::fromUtf8(e.text.data(), static_cast<qsizetype>(len)));
    if (e.from != e.to) {
        // The states in the GUI's words ("Emergency stop", "Not-Halt"), not the enum's names.
        const QString transition =
            QStringLiteral("%1 -> %2").arg(stateWord(e.from), stateWord(e.to));
        msg = msg.isEmpty() ? transition : QStringLiteral("%1 (%2)").arg(msg, transition);
        const QString hint = clearHint(e.to);
        if (!hint.isEmpty()) msg += QStringLiteral(". ") + hint;
    }
    const QDateTime when =
        e.wall_ms > 0 ? QDateTime::fromMSecsSinceEpoch(e.wall_ms) : QDateTime::currentDateTime();
    add(e.severity, msg, when);
}

void EventLogPanel::clear() {
    table_->setRowCount(0);
}

int EventLogPanel::rowCount() const {
    return table_->rowCount();
}

QString EventLogPanel::message(int row) const {
    auto* it = table_->item(row, 2);
    return it ? it->text() : QString();
}

} // namespace CutCell::ui
