#include "ui/panels/history_panel.h"

#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/machine_module.h"
#include "core/machine/machine_registry.h"

#ifdef CUTCELL_HAVE_PLOTS
#include "plots/history_charts_widget.h"
#endif

#include <QComboBox>
#include <QDateEdit>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPageSize>
#include <QPdfWriter>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSaveFile>
#include <QScrollArea>
#include <QSplitter>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTextDocument>
#include <QVBoxLayout>

#include <exception>
#include <map>

namespace CutCell::ui {
namespace {

QString localTime(std::int64_t ms) {
    if (ms <= 0) return QStringLiteral("-");
    return QDateTime::fromMSecsSinceEpoch(ms).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
}

QString csvField(const QString& v) {
    if (!v.contains(QRegularExpression(QStringLiteral("[,\"\\n\\r]")))) return v;
    QString q = v;
    q.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

// What a run made, in its machine's words, from summary.json's "made" ("" when none).
QString madeText(const std::string& madeJson) {
    if (madeJson.empty()) return {};
    try {
        const cutcell::json::Value made = cutcell::json::parse(madeJson);
        QStringList parts;
        if (!made.isObject()) return QString::fromStdString(madeJson);
        for (const auto& [k, v] : made.asObject())
            if (v.isNumber())
                parts << QStringLiteral("%1 %2").arg(QString::fromStdString(k),
                                                     QString::number(v.asNumber(), 'g', 8));
        return parts.join(QStringLiteral(", "));
    } catch (const std::exception&) {
        return QString::fromStdString(madeJson);
    }
}

const QStringList kColumns = {QStringLiteral("id"),        QStringLiteral("started"),
                              QStringLiteral("machine"),   QStringLiteral("job"),
                              QStringLiteral("operator"),  QStringLiteral("outcome"),
                              QStringLiteral("cycle (s)"), QStringLiteral("alarms")};

} // namespace

QString HistoryPanel::alarmKind(const QString& text) {
    static const QRegularExpression figures(QStringLiteral("-?\\d+\\.\\d+|\\d{3,}"));
    QString kind = text;
    kind.replace(figures, QStringLiteral("#"));
    return kind;
}

HistoryPanel::HistoryPanel(const cutcell::RunHistory* history, QWidget* parent)
    : QWidget(parent), history_(history), machine_(new QComboBox(this)), job_(new QLineEdit(this)),
      outcome_(new QComboBox(this)), since_(new QDateEdit(this)),
      table_(new QTableWidget(0, static_cast<int>(kColumns.size()), this)),
      details_(new QPlainTextEdit(this)), summary_(new QLabel(this)) {
    setObjectName("historyPanel");
    machine_->setObjectName("historyMachine");
    job_->setObjectName("historyJob");
    outcome_->setObjectName("historyOutcome");
    since_->setObjectName("historySince");
    table_->setObjectName("historyRuns");
    details_->setObjectName("historyDetails");
    summary_->setObjectName("historySummary");
    machine_->addItem(tr("every machine"), QString());
    for (const cutcell::MachineModule* m : cutcell::machines())
        machine_->addItem(QString::fromStdString(m->title()), QString::fromStdString(m->id()));
    outcome_->addItem(tr("every outcome"), QString());
    for (const char* o : {"completed", "aborted", "emergency stop", "interrupted"})
        outcome_->addItem(QString::fromLatin1(o), QString::fromLatin1(o));
    outcome_->addItem(tr("faults"), QStringLiteral("fault"));
    job_->setPlaceholderText(tr("job name contains"));
    since_->setDisplayFormat(QStringLiteral("yyyy-MM-dd"));
    since_->setCalendarPopup(true);
    since_->setDate(QDate::currentDate().addDays(-7));
    table_->setHorizontalHeaderLabels({tr("Run"), tr("Started"), tr("Machine"), tr("Job"),
                                       tr("Operator"), tr("Outcome"), tr("Cycle (s)"),
                                       tr("Alarms")});
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setStretchLastSection(true);
    details_->setReadOnly(true);

    auto* refreshButton = new QPushButton(tr("Refresh"), this);
    auto* csv = new QPushButton(tr("Shift report (CSV)..."), this);
    auto* pdf = new QPushButton(tr("Shift report (PDF)..."), this);
    refreshButton->setObjectName("historyRefresh");
    csv->setObjectName("historyCsv");
    pdf->setObjectName("historyPdf");
    auto* filters = new QHBoxLayout;
    filters->addWidget(new QLabel(tr("Since"), this));
    filters->addWidget(since_);
    filters->addWidget(machine_, 1);
    filters->addWidget(outcome_);
    filters->addWidget(job_, 1);
    auto* actions = new QHBoxLayout; // a second row: the bottom pane is narrow at 1280x720
    actions->addWidget(summary_, 1);
    actions->addWidget(refreshButton);
    actions->addWidget(csv);
    actions->addWidget(pdf);

    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(table_);
    split->addWidget(details_);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    // All of it in a scroll area: the bottom tabs take the tallest page's minimum height, and
    // the History page must not take height from the 3D view and the plots above it.
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto* content = new QWidget(scroll);
    content->setMinimumHeight(420);
    scroll->setWidget(content);
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(scroll);
    auto* v = new QVBoxLayout(content);
    v->addLayout(filters);
    v->addLayout(actions);
    auto* body = new QSplitter(Qt::Vertical, this);
    body->addWidget(split);
#ifdef CUTCELL_HAVE_PLOTS
    charts_ = new cutcell::plots::HistoryChartsWidget(this);
    body->addWidget(charts_);
#endif
    v->addWidget(body, 1);

    connect(refreshButton, &QPushButton::clicked, this, &HistoryPanel::refresh);
    connect(machine_, &QComboBox::currentIndexChanged, this, &HistoryPanel::refresh);
    connect(outcome_, &QComboBox::currentIndexChanged, this, &HistoryPanel::refresh);
    connect(since_, &QDateEdit::dateChanged, this, &HistoryPanel::refresh);
    connect(job_, &QLineEdit::textChanged, this, &HistoryPanel::refresh);
    connect(table_, &QTableWidget::itemSelectionChanged, this, &HistoryPanel::showDetails);
    const auto save = [this](bool asPdf) {
        const QString suggested =
            QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
                .filePath(QStringLiteral("shift-report-%1.%2")
                              .arg(QDate::currentDate().toString(Qt::ISODate),
                                   asPdf ? QStringLiteral("pdf") : QStringLiteral("csv")));
        // The E-STOP key still acts while the dialog is open (ControlPanel's event filter).
        const QString path = QFileDialog::getSaveFileName(this, tr("Shift report"), suggested,
                                                          asPdf ? QStringLiteral("PDF (*.pdf)")
                                                                : QStringLiteral("CSV (*.csv)"));
        if (path.isEmpty()) return;
        QString why;
        const bool ok = asPdf ? writePdf(path, &why) : writeCsv(path, &why);
        summary_->setText(ok ? tr("Shift report written: %1").arg(path) : why);
    };
    connect(csv, &QPushButton::clicked, this, [save] { save(false); });
    connect(pdf, &QPushButton::clicked, this, [save] { save(true); });
    refresh();
}

void HistoryPanel::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    refresh();
}

void HistoryPanel::setSince(const QDate& day) {
    since_->setDate(day);
    refresh();
}

void HistoryPanel::setMachineFilter(const QString& machineId) {
    machine_->setCurrentIndex(std::max(0, machine_->findData(machineId)));
}

void HistoryPanel::setJobFilter(const QString& text) {
    job_->setText(text);
}

void HistoryPanel::setOutcomeFilter(const QString& outcome) {
    outcome_->setCurrentIndex(std::max(0, outcome_->findData(outcome)));
}

void HistoryPanel::refresh() {
    shown_.clear();
    table_->setRowCount(0);
    details_->clear();
    if (!history_) {
        summary_->setText(tr("No production record at this station (--record off)."));
        return;
    }
    cutcell::RunQuery q;
    q.since_ms = QDateTime(since_->date(), QTime(0, 0)).toMSecsSinceEpoch();
    q.machine = machine_->currentData().toString().toStdString();
    const QString outcome = outcome_->currentData().toString();
    std::vector<cutcell::RecordedRun> runs;
    try {
        runs = history_->runs(q);
    } catch (const std::exception& e) {
        summary_->setText(tr("The production record cannot be read: %1").arg(e.what()));
        return;
    }
    const QString job = job_->text().trimmed();
    for (cutcell::RecordedRun& r : runs) {
        const QString o = QString::fromStdString(r.outcome);
        if (!outcome.isEmpty() && !(o == outcome || (outcome == "fault" && o.startsWith(outcome))))
            continue;
        if (!job.isEmpty() &&
            !QString::fromStdString(r.job_name).contains(job, Qt::CaseInsensitive))
            continue;
        shown_.push_back(std::move(r));
    }
    table_->setRowCount(static_cast<int>(shown_.size()));
    double total = 0;
    int completed = 0;
#ifdef CUTCELL_HAVE_PLOTS
    std::vector<cutcell::plots::CycleBar> bars;
    std::map<QString, int> kinds;
#endif
    for (size_t i = 0; i < shown_.size(); ++i) {
        const cutcell::RecordedRun& r = shown_[i];
        const QStringList cells = {
            QString::number(r.id),
            localTime(r.started_ms),
            QString::fromStdString(r.machine),
            QString::fromStdString(r.job_name),
            QString::fromStdString(r.operator_name),
            r.outcome.empty() ? tr("running") : QString::fromStdString(r.outcome),
            r.ended_ms ? QString::number(r.cycle_time_s, 'f', 1) : QStringLiteral("-"),
            QString::number(r.alarms)};
        for (int c = 0; c < cells.size(); ++c)
            table_->setItem(static_cast<int>(i), c, new QTableWidgetItem(cells[c]));
        if (r.ended_ms) total += r.cycle_time_s;
        if (r.outcome == "completed") ++completed;
#ifdef CUTCELL_HAVE_PLOTS
        if (r.ended_ms)
            bars.push_back({QString::number(r.id), r.cycle_time_s, r.outcome == "completed"});
        if (r.alarms > 0) try {
                for (const cutcell::RunAlarmNote& a : history_->alarmsOf(r.id))
                    ++kinds[alarmKind(QString::fromStdString(a.text))];
            } catch (const std::exception&) {
            }
#endif
    }
    table_->resizeColumnsToContents();
#ifdef CUTCELL_HAVE_PLOTS
    std::vector<cutcell::plots::ParetoBar> pareto;
    for (const auto& [text, count] : kinds)
        pareto.push_back({text, count});
    charts_->setCycleTimes(bars);
    charts_->setAlarms(std::move(pareto));
#endif
    summary_->setText(tr("%1 run(s), %2 completed, %3 s of cycle time")
                          .arg(shown_.size())
                          .arg(completed)
                          .arg(QString::number(total, 'f', 1)));
}

void HistoryPanel::selectRun(int row) {
    table_->selectRow(row);
    showDetails();
}

QString HistoryPanel::details() const {
    return details_->toPlainText();
}

void HistoryPanel::showDetails() {
    const int row = table_->currentRow();
    if (row < 0 || row >= static_cast<int>(shown_.size()) || !history_) {
        details_->clear();
        return;
    }
    const cutcell::RecordedRun& r = shown_[static_cast<size_t>(row)];
    QStringList lines;
    lines << tr("Run %1: %2 on the %3")
                 .arg(r.id)
                 .arg(QString::fromStdString(r.job_name), QString::fromStdString(r.machine));
    lines << tr("Operator: %1").arg(QString::fromStdString(r.operator_name));
    lines << tr("Started %1, ended %2").arg(localTime(r.started_ms), localTime(r.ended_ms));
    lines << tr("Outcome: %1, cycle time %2 s")
                 .arg(QString::fromStdString(r.outcome), QString::number(r.cycle_time_s, 'f', 3));
    if (const QString made = madeText(r.made_json); !made.isEmpty())
        lines << tr("Made: %1").arg(made);
    if (!r.stop_json.empty())
        lines << tr("Stopped at: %1").arg(QString::fromStdString(r.stop_json).simplified());
    lines << tr("Job fingerprint: %1").arg(QString::fromStdString(r.job_hash));
    if (!r.run_dir.empty()) lines << tr("Run log: %1").arg(QString::fromStdString(r.run_dir));
    try {
        const auto alarms = history_->alarmsOf(r.id);
        lines << tr("Alarms: %1").arg(alarms.size());
        for (const cutcell::RunAlarmNote& a : alarms)
            lines << QStringLiteral("  %1  %2  %3")
                         .arg(localTime(a.unix_ms), QString::fromStdString(a.severity),
                              QString::fromStdString(a.text));
    } catch (const std::exception& e) {
        lines << tr("Alarms cannot be read: %1").arg(e.what());
    }
    details_->setPlainText(lines.join(QLatin1Char('\n')));
}

bool HistoryPanel::writeCsv(const QString& path, QString* why) const {
    QStringList out;
    out << kColumns.join(QLatin1Char(','));
    double total = 0;
    for (const cutcell::RecordedRun& r : shown_) {
        out << QStringList{QString::number(r.id),
                           localTime(r.started_ms),
                           csvField(QString::fromStdString(r.machine)),
                           csvField(QString::fromStdString(r.job_name)),
                           csvField(QString::fromStdString(r.operator_name)),
                           csvField(QString::fromStdString(r.outcome)),
                           QString::number(r.cycle_time_s, 'f', 3),
                           QString::number(r.alarms)}
                   .join(QLatin1Char(','));
        total += r.ended_ms ? r.cycle_time_s : 0;
    }
    out << QStringLiteral("total,,,,,%1 runs,%2,").arg(shown_.size()).arg(total, 0, 'f', 3);
    try {
        cutcell::writeFileAtomically(path.toStdString(),
                                     out.join(QLatin1Char('\n')).toStdString() + "\n");
    } catch (const std::exception& e) {
        if (why) *why = tr("Cannot write %1: %2").arg(path, e.what());
        return false;
    }
    return true;
}

QString HistoryPanel::reportText() const {
    QString html = QStringLiteral("<h2>%1</h2><p>%2</p><table border='1' cellspacing='0' "
                                  "cellpadding='3'><tr>")
                       .arg(tr("Shift report"), summary_->text().toHtmlEscaped());
    for (const QString& c : kColumns)
        html += QStringLiteral("<th>%1</th>").arg(c.toHtmlEscaped());
    html += QStringLiteral("</tr>");
    for (const cutcell::RecordedRun& r : shown_) {
        html += QStringLiteral("<tr>");
        for (const QString& c :
             {QString::number(r.id), localTime(r.started_ms), QString::fromStdString(r.machine),
              QString::fromStdString(r.job_name), QString::fromStdString(r.operator_name),
              QString::fromStdString(r.outcome), QString::number(r.cycle_time_s, 'f', 1),
              QString::number(r.alarms)})
            html += QStringLiteral("<td>%1</td>").arg(c.toHtmlEscaped());
        html += QStringLiteral("</tr>");
    }
    return html + QStringLiteral("</table>");
}

bool HistoryPanel::writePdf(const QString& path, QString* why) const {
    QSaveFile file(path); // written whole or not at all
    if (!file.open(QIODevice::WriteOnly)) {
        if (why) *why = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    {
        QPdfWriter pdf(&file);
        pdf.setPageSize(QPageSize(QPageSize::A4));
        pdf.setTitle(tr("Shift report"));
        QTextDocument doc;
        doc.setHtml(reportText());
        doc.print(&pdf);
    }
    if (!file.commit()) {
        if (why) *why = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace CutCell::ui
