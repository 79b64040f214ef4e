// Issue 25's History view against a real production record (SQLite, written through the same
// calls the run logger makes): the filters (day, machine, outcome, job), a run's details, the
// alarm Pareto (one bar per kind of alarm, measured figures aside: counts and cumulative share
// recomputed here from the alarms written), the cycle-time chart, and the shift report as CSV
// (one line per run and the totals, a decimal point under a German locale) and as PDF (read
// back with poppler's pdftotext where it is installed).
#include "devices/record/run_record_store.h"
#include "plots/history_charts_widget.h"
#include "ui/panels/history_panel.h"

#include <QFile>
#include <QLocale>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using CutCell::ui::HistoryPanel;

namespace {

std::string jobFor(const char* machine, const char* name) {
    return std::string(R"({"schema": 2, "name": ")") + name + R"(", "machine": {"kind": ")" +
           machine + R"("}})";
}

} // namespace

class TestHistoryPanel : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    std::unique_ptr<cutcell::RunRecordStore> record_;
    std::int64_t now_ = 0;

  private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        record_ =
            std::make_unique<cutcell::RunRecordStore>(dir_.filePath("p.db").toStdString(), "ada");
        now_ = QDateTime::currentMSecsSinceEpoch();
        const std::int64_t day = 24LL * 3600 * 1000;
        // An old run (ten days ago), then three today: a saw's fault with two following-error
        // alarms, a completed saw run, and a robot's E-STOP with a following error and a lost
        // node.
        record_->opened(
            {1, "old saw job", jobFor("flying_saw", "old saw job"), "", now_ - 10 * day});
        record_->closed({"completed", now_ - 10 * day + 60000, R"({"elapsed_s": 60})"});
        record_->opened({2, "saw 6 m", jobFor("flying_saw", "saw 6 m"), "", now_ - 3000000});
        record_->alarm(
            {now_ - 2990000, "fault", "axis 1 (carriage): following error 2.31 mm > 2.00 mm"});
        record_->alarm(
            {now_ - 2980000, "fault", "axis 1 (carriage): following error 2.47 mm > 2.00 mm"});
        record_->closed({"fault: axis 1", now_ - 2970000,
                         R"({"elapsed_s": 30.5, "made": {"pieces": 4}, "stop": {"piece": 5}})"});
        record_->opened({3, "saw 6 m", jobFor("flying_saw", "saw 6 m"), "", now_ - 2000000});
        record_->closed(
            {"completed", now_ - 1930000, R"({"elapsed_s": 63.25, "made": {"pieces": 10}})"});
        record_->opened(
            {4, "branch hole", jobFor("pipe_robot_6axis", "branch hole"), "", now_ - 1000000});
        record_->alarm(
            {now_ - 990000, "fault", "axis 2 (theta1): following error 0.912 deg > 0.500 deg"});
        record_->alarm({now_ - 985000, "error", "node 4: no heartbeat for 310 ms"});
        record_->alarm(
            {now_ - 980000, "fault", "axis 1 (carriage): following error 3.02 mm > 2.00 mm"});
        record_->closed({"emergency stop", now_ - 970000, R"({"elapsed_s": 12})"});
    }

    void theFiltersNarrowTheRuns() {
        HistoryPanel panel(record_.get());
        panel.setSince(QDate::currentDate().addDays(-1));
        QCOMPARE(panel.shown().size(), size_t{3});
        panel.setSince(QDate::currentDate().addDays(-30));
        QCOMPARE(panel.shown().size(), size_t{4});
        panel.setMachineFilter("flying_saw");
        QCOMPARE(panel.shown().size(), size_t{3});
        panel.setOutcomeFilter("fault"); // every "fault: ..."
        QCOMPARE(panel.shown().size(), size_t{1});
        QCOMPARE(panel.shown()[0].outcome, std::string("fault: axis 1"));
        panel.setOutcomeFilter("");
        panel.setJobFilter("OLD");
        QCOMPARE(panel.shown().size(), size_t{1});
        QCOMPARE(panel.shown()[0].job_name, std::string("old saw job"));
    }

    void aRunsDetailsSayWhatItMadeWhereItStoppedAndItsAlarms() {
        HistoryPanel panel(record_.get());
        panel.setSince(QDate::currentDate().addDays(-1));
        panel.selectRun(0); // the saw's fault
        const QString d = panel.details();
        QVERIFY2(d.contains("Made: pieces 4"), qPrintable(d));
        QVERIFY2(d.contains("\"piece\": 5") || d.contains("\"piece\":5"), qPrintable(d));
        QVERIFY2(d.contains("Alarms: 2") && d.contains("following error 2.47 mm"), qPrintable(d));
        QVERIFY2(d.contains("Operator: ada"), qPrintable(d));
    }

    // One bar per kind (the figures aside), most frequent first; the cumulative share is the
    // running sum over the total, recomputed here from the four alarms written above.
    void theParetoCountsEachKindOfAlarm() {
        HistoryPanel panel(record_.get());
        panel.setSince(QDate::currentDate().addDays(-1));
        const auto bars = panel.charts()->paretoShown();
        QCOMPARE(bars.size(), size_t{3});
        QCOMPARE(bars[0].label, QString("axis 1 (carriage): following error # mm > # mm"));
        QCOMPARE(bars[0].count, 3);
        QCOMPARE(bars[1].count + bars[2].count, 2);
        const auto cumulative = panel.charts()->paretoCumulative();
        QCOMPARE(cumulative.size(), size_t{3});
        QCOMPARE(cumulative[0], 100.0 * 3 / 5);
        QCOMPARE(cumulative[2], 100.0);
        QCOMPARE(HistoryPanel::alarmKind("node 4: no heartbeat for 310 ms"),
                 QString("node 4: no heartbeat for # ms"));
        if (const QByteArray shot = qgetenv("CUTCELL_HISTORY_PNG"); !shot.isEmpty()) {
            panel.resize(1200, 560);
            panel.show();
            QTest::qWait(200);
            panel.grab().save(QString::fromLocal8Bit(shot));
        }
    }

    // CSV: a line per run and the totals, with a decimal point under a German locale.
    void theShiftReportCsvHasEveryRunAndTheTotals() {
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        HistoryPanel panel(record_.get());
        panel.setSince(QDate::currentDate().addDays(-1));
        const QString path = dir_.filePath("shift.csv");
        QString why;
        QVERIFY2(panel.writeCsv(path, &why), qPrintable(why));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3 + 2);
        QVERIFY2(lines[2].contains(",63.250,"), qPrintable(lines[2]));
        QCOMPARE(lines.last(), QString("total,,,,,3 runs,%1,").arg(30.5 + 63.25 + 12, 0, 'f', 3));
        QVERIFY(!panel.writeCsv(dir_.filePath("no/such/folder/shift.csv"), &why));
        QVERIFY2(why.contains("no/such/folder"), qPrintable(why));
        QLocale::setDefault(QLocale::c());
    }

    void theShiftReportPdfReadsBack() {
        HistoryPanel panel(record_.get());
        panel.setSince(QDate::currentDate().addDays(-1));
        const QString path = dir_.filePath("shift.pdf");
        QString why;
        QVERIFY2(panel.writePdf(path, &why), qPrintable(why));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.read(5) == "%PDF-");
        const QString tool = QStandardPaths::findExecutable("pdftotext");
        if (tool.isEmpty())
            QSKIP("pdftotext (poppler-utils) not installed: the text not read back");
        QProcess p;
        p.start(tool, {path, "-"});
        QVERIFY(p.waitForFinished(30000));
        const QString text = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(text.contains("Shift report") && text.contains("branch hole") &&
                     text.contains("emergency stop"),
                 qPrintable(text));
    }
};

QTEST_MAIN(TestHistoryPanel)
#include "test_history_panel.moc"
