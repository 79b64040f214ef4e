#include "ui/panels/alarm_panel.h"
#include "ui/panels/engine_text.h"

#include "ui/panels/run_words.h"

#include "ui/panels/event_log_panel.h"

#include <QDir>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QSaveFile>
#include <QShortcut>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

#include <cstring>

namespace CutCell::ui {

using cutcell::EngineState;
using cutcell::EventKind;

namespace {
enum Column { ColTime, ColSource, ColText, ColAction, ColState, ColCount };

QString stateText(const Alarm& a) {
    if (a.active) return a.acknowledged ? QObject::tr("active, ack.") : QObject::tr("ACTIVE");
    return a.acknowledged ? QObject::tr("past, ack.") : QObject::tr("past");
}

QString csvField(QString s) {
    s.replace('"', QStringLiteral("\"\""));
    return '"' + s + '"';
}
} // namespace

AlarmPanel::AlarmPanel(QWidget* parent)
    : QWidget(parent), summary_(new QLabel(this)), ack_(new QPushButton(tr("Acknowledge"), this)),
      table_(new QTableWidget(0, ColCount, this)) {
    table_->setTabKeyNavigation(false); // Tab leaves the table (it walked its cells for ever)
    setObjectName("alarmPanel");
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    auto* top = new QHBoxLayout;
    summary_->setObjectName("alarmSummary");
    top->addWidget(summary_, 1);
    ack_->setObjectName("alarmAcknowledge");
    ack_->setToolTip(tr("The operator has seen the alarms; they stay active until Reset [%1].")
                         .arg(QLatin1String(kAcknowledgeKey)));
    connect(ack_, &QPushButton::clicked, this, &AlarmPanel::acknowledgeAll);
    auto* ackKey = new QShortcut(QKeySequence(QString::fromLatin1(kAcknowledgeKey)), this);
    ackKey->setContext(Qt::ApplicationShortcut);
    ackKey->setAutoRepeat(false);
    connect(ackKey, &QShortcut::activated, this, [this] {
        if (ack_->isEnabled()) acknowledgeAll();
    });
    top->addWidget(ack_);
    v->addLayout(top);
    table_->setHorizontalHeaderLabels(
        {tr("Time"), tr("Source"), tr("Alarm"), tr("What to do"), tr("State")});
    const QFontMetrics fm(table_->font());
    auto* h = table_->horizontalHeader();
    h->setSectionResizeMode(QHeaderView::Interactive);
    table_->setColumnWidth(ColTime, fm.horizontalAdvance(QStringLiteral("00:00:00.000")) + 20);
    table_->setColumnWidth(ColSource,
                           fm.horizontalAdvance(QStringLiteral("axis 2 (q2 shoulder)")) + 16);
    table_->setColumnWidth(ColText, 320);
    table_->setColumnWidth(ColState, fm.horizontalAdvance(QStringLiteral("active, ack.")) + 20);
    h->setSectionResizeMode(ColAction, QHeaderView::Stretch);
    table_->verticalHeader()->hide();
    table_->verticalHeader()->setDefaultSectionSize(24);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setWordWrap(false);
    v->addWidget(table_, 1);
    refreshSummary();
}

QString AlarmPanel::sourceOf(const QString& text, const cutcell::RunTerms& terms) {
    static const QRegularExpression axis(QStringLiteral("axis (\\d+)( \\([^)]*\\))?"));
    static const QRegularExpression node(QStringLiteral("node (\\d+)"));
    if (const auto m = node.match(text); m.hasMatch()) return m.captured(0);
    if (const auto m = axis.match(text); m.hasMatch()) return m.captured(0);
    const QString tool = QString::fromStdString(terms.tool);
    if (!tool.isEmpty() && text.contains(tool, Qt::CaseInsensitive)) return toolWord(terms);
    return tr("engine");
}

QString AlarmPanel::actionFor(const QString& text, bool emergencyStop) {
    if (emergencyStop) return EventLogPanel::clearHint(EngineState::EmergencyStop);
    const auto has = [&text](const char* s) {
        return text.contains(QLatin1String(s), Qt::CaseInsensitive);
    };
    QString what;
    if (has("following error"))
        what = tr("Check the axis for a collision or binding, then its gains and the "
                  "following error limit.");
    else if (has("drive fault"))
        what = tr("Look the drive's fault code up in its manual (Devices tab); remove the cause.");
    else if (has("stale") || has("frozen") || has("feedback"))
        what = tr("Check the encoder, its cable and the bus.");
    else if (has("left operation"))
        what = tr("Check the drive's power and its enable chain.");
    else if (has("arc"))
        what = tr("Check gas, consumables and the work clamp.");
    else if (has("heartbeat") || has("bus") || has("node"))
        what = tr("Check the CAN cable, the node's power and the bus termination.");
    else if (has("settle"))
        what = tr("Check the axes' tuning and the in-position window.");
    const QString clear = EventLogPanel::clearHint(EngineState::Fault);
    return what.isEmpty() ? clear : what + ' ' + clear;
}

void AlarmPanel::addEngineEvent(const cutcell::EngineEvent& e) {
    const bool estop = e.kind == EventKind::Transition && e.to == EngineState::EmergencyStop &&
                       e.from != EngineState::EmergencyStop;
    if (!estop && e.kind != EventKind::Fault) return;
    const auto len = strnlen(e.text.data(), e.text.size());
    // Source and action are told from core's English words; the operator reads the text in
    // the GUI's language.
    const QString english = QString::fromUtf8(e.text.data(), static_cast<qsizetype>(len));
    Alarm a;
    a.text = engineText(english);
    a.logged = english;
    a.time =
        e.wall_ms > 0 ? QDateTime::fromMSecsSinceEpoch(e.wall_ms) : QDateTime::currentDateTime();
    a.source = estop ? tr("operator (E-STOP)") : sourceOf(english, terms_);
    a.action = actionFor(english, estop);
    a.run_id = e.run_id;
    raise(a);
}

void AlarmPanel::raise(const Alarm& alarm) {
    alarms_.push_back(alarm);
    const int row = table_->rowCount();
    table_->insertRow(row);
    for (int c = 0; c < ColCount; ++c)
        table_->setItem(row, c, new QTableWidgetItem);
    refreshRow(row);
    table_->scrollToBottom();
    refreshSummary();
    writeRunFiles();
    emit raised(alarm);
}

void AlarmPanel::refreshRow(int row) {
    const Alarm& a = alarms_[static_cast<size_t>(row)];
    const QString texts[ColCount] = {a.time.toString(QStringLiteral("HH:mm:ss.zzz")), a.source,
                                     a.text, a.action, stateText(a)};
    const QColor colour = a.active ? (a.acknowledged ? QColor(255, 160, 80) : QColor(255, 95, 85))
                                   : QColor(150, 155, 165);
    for (int c = 0; c < ColCount; ++c) {
        QTableWidgetItem* it = table_->item(row, c);
        it->setText(texts[c]);
        it->setToolTip(texts[c]);
        it->setForeground(colour);
        QFont f = it->font();
        f.setBold(a.active && !a.acknowledged);
        it->setFont(f);
    }
}

void AlarmPanel::setState(EngineState state) {
    if (state == EngineState::EmergencyStop || state == EngineState::Fault) return;
    bool any = false;
    for (Alarm& a : alarms_)
        if (a.active) {
            a.active = false;
            any = true;
        }
    if (!any) return;
    for (int r = 0; r < table_->rowCount(); ++r)
        refreshRow(r);
    refreshSummary();
    writeRunFiles();
}

void AlarmPanel::acknowledgeAll() {
    bool any = false;
    for (Alarm& a : alarms_)
        if (!a.acknowledged) {
            a.acknowledged = true;
            any = true;
        }
    if (!any) return;
    for (int r = 0; r < table_->rowCount(); ++r)
        refreshRow(r);
    refreshSummary();
    writeRunFiles();
}

int AlarmPanel::activeCount() const {
    return static_cast<int>(
        std::count_if(alarms_.begin(), alarms_.end(), [](const Alarm& a) { return a.active; }));
}

int AlarmPanel::unacknowledgedCount() const {
    return static_cast<int>(std::count_if(alarms_.begin(), alarms_.end(),
                                          [](const Alarm& a) { return !a.acknowledged; }));
}

void AlarmPanel::refreshSummary() {
    const int active = activeCount(), unack = unacknowledgedCount();
    summary_->setText(alarms_.empty() ? tr("No alarms.")
                                      : tr("%1 active, %2 not acknowledged, %3 in the list")
                                            .arg(active)
                                            .arg(unack)
                                            .arg(alarms_.size()));
    ack_->setEnabled(unack > 0);
    emit changed(active, unack);
}

void AlarmPanel::setRunDirectory(std::uint32_t runId, const QString& dir) {
    if (dir.isEmpty()) return;
    runDirs_[runId] = dir;
    writeRunFiles();
}

QByteArray AlarmPanel::runJson(std::uint32_t runId) const {
    QJsonArray list;
    for (const Alarm& a : alarms_) {
        if (a.run_id != runId) continue;
        list.append(QJsonObject{{"time", a.time.toUTC().toString(Qt::ISODateWithMs)},
                                {"source", a.source},
                                {"text", a.logged.isEmpty() ? a.text : a.logged},
                                {"action", a.action},
                                {"active", a.active},
                                {"acknowledged", a.acknowledged},
                                {"run_id", static_cast<double>(a.run_id)}});
    }
    return QJsonDocument(list).toJson(QJsonDocument::Indented);
}

void AlarmPanel::writeRunFiles() {
    for (const auto& [run, dir] : runDirs_) {
        const bool any = std::any_of(alarms_.begin(), alarms_.end(),
                                     [run = run](const Alarm& a) { return a.run_id == run; });
        if (!any) continue;
        QSaveFile file(QDir(dir).filePath(QStringLiteral("alarms.json")));
        if (file.open(QIODevice::WriteOnly)) {
            file.write(runJson(run));
            file.commit();
        }
    }
}

bool AlarmPanel::exportCsv(const QString& path, QString* error) const {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error)
            *error = tr("Cannot write the alarm list '%1': %2").arg(path, file.errorString());
        return false;
    }
    QByteArray out = "time_utc,run,source,alarm,what_to_do,active,acknowledged\n";
    for (const Alarm& a : alarms_)
        out += QStringList{a.time.toUTC().toString(Qt::ISODateWithMs),
                           QString::number(a.run_id),
                           csvField(a.source),
                           csvField(a.logged.isEmpty() ? a.text : a.logged),
                           csvField(a.action),
                           a.active ? "1" : "0",
                           a.acknowledged ? "1" : "0"}
                   .join(',')
                   .toUtf8() +
               '\n';
    file.write(out);
    if (!file.commit()) {
        if (error)
            *error = tr("Cannot write the alarm list '%1': %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace CutCell::ui
