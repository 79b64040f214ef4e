// The run model in the operator station, one row per machine (issue 20): the parameter tabs
// show no Pipes page where the machine has no pipes; a run stopped in the middle by the E-STOP
// shows the machine's own stop figures (the saw's piece and the pieces made, the crank's stroke,
// a torch machine's point and millimetres); the engine's texts and the alarm list name the
// machine's tool; every engine limit on the Cycle & devices page is in its axes' unit.
//
// The expectations come from the core module (its axes, its program's terms) and from the
// machine's shipped job, not from the panels under test.
#include "sim_rig.h"

#include "core/engine/run_terms.h"
#include "core/machine/machine_module.h"
#include "core/machine/machine_registry.h"
#include "core/machines/flying_saw/flying_saw_module.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"
#include "core/machines/quick_return/quick_return_spec.h"
#include "core/machines/section_steel/section_steel_module.h"
#include "main_window_run.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/panels/alarm_panel.h"
#include "ui/panels/control_panel.h"
#include "ui/panels/engine_text.h"
#include "ui/panels/progress_panel.h"
#include "ui/panels/state_lamps.h"
#include "ui/run_controller.h"

#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QtTest>

using cutcell::EngineState;
using cutcell::WorkCount;
using CutCell::ui::MainWindow;

namespace {

void newJobFor(MainWindow& w, const std::string& id) {
    QVERIFY(w.newJob(id));
    auto job = w.editor()->job();
    job.engine.runs_dir = ""; // no run logs in the source tree
    w.editor()->setJob(job);
}

// The unit label next to a form field (JobForm::addRow puts it in the field's row).
QString unitOf(QWidget* field) {
    if (!field || !field->parentWidget()) return {};
    for (auto* l : field->parentWidget()->findChildren<QLabel*>("unitLabel"))
        return l->text();
    return {};
}

void machineRows() {
    QTest::addColumn<QString>("id");
    QTest::addColumn<bool>("pipes"); // the machine cuts a pipe joint: main and branch pipe
    QTest::newRow("pipe robot") << QString(cutcell::kPipeRobotId) << true;
    QTest::newRow("profile cutter") << QString(cutcell::kProfileCutterId) << true;
    QTest::newRow("section steel") << QString(cutcell::kSectionSteelId) << false;
    QTest::newRow("flying saw") << QString(cutcell::kFlyingSawId) << false;
    QTest::newRow("quick return") << QString(cutcell::kQuickReturnId) << false;
}

} // namespace

class TestRunModel : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    // The tool lamp names the new job's machine's tool at once, before its first plan
    // (it said "Torch" on the saw until a plan came), also after another machine's job.
    void toolLampBeforeThePlan_data() { machineRows(); }
    void toolLampBeforeThePlan() {
        QFETCH(QString, id);
        MainWindow w(nullptr);
        const std::string other =
            id == cutcell::kFlyingSawId ? cutcell::kQuickReturnId : cutcell::kFlyingSawId;
        newJobFor(w, other);
        newJobFor(w, id.toStdString()); // no events processed: no plan can have come
        const cutcell::MachineModule* module = cutcell::findMachine(id.toStdString());
        QVERIFY(module);
        const cutcell::MachinePlan plan = module->plan(w.editor()->job());
        QVERIFY2(plan.ok() && plan.program, plan.outcome.message.c_str());
        auto* lamps = w.findChild<CutCell::ui::StateLamps*>();
        QVERIFY(lamps);
        QCOMPARE(lamps->lamp(CutCell::ui::StateLamps::Torch)->text().toLower(),
                 QString::fromStdString(plan.program->terms.tool));
    }

    void pipesTabOnlyWithPipes_data() { machineRows(); }
    void pipesTabOnlyWithPipes() {
        QFETCH(QString, id);
        QFETCH(bool, pipes);
        MainWindow w(nullptr);
        newJobFor(w, id.toStdString());
        QCOMPARE(w.parameters()->tabShown("Pipes"), pipes);
        QVERIFY(w.parameters()->tabShown("Job")); // every job has a name
        QCOMPARE(w.parameters()->fieldFor("name") != nullptr, true);
    }

    void engineFieldsInTheirAxesUnit_data() { machineRows(); }
    void engineFieldsInTheirAxesUnit() {
        QFETCH(QString, id);
        MainWindow w(nullptr);
        newJobFor(w, id.toStdString());
        const cutcell::MachineModule* m = cutcell::findMachine(id.toStdString());
        QVERIFY(m);
        bool rotary = false, linear = false;
        for (const cutcell::AxisInfo& a : m->axes(w.editor()->job()))
            (a.unit == cutcell::AxisUnit::Linear ? linear : rotary) = true;
        struct Field {
            const char* key;
            const char* unit;
            bool linear;
        };
        for (const Field& f : {Field{"engine.following_error_limit_deg", "deg", false},
                               Field{"engine.home_speed_deg_s", "deg/s", false},
                               Field{"engine.following_error_limit_mm", "mm", true},
                               Field{"engine.home_speed_mm_s", "mm/s", true}}) {
            QWidget* field = w.parameters()->fieldFor(f.key);
            QVERIFY2(field, f.key);
            QCOMPARE(unitOf(field), QString(f.unit));
            // Usable only where the machine has an axis of that kind.
            QVERIFY2(field->isEnabled() == (f.linear ? linear : rotary), f.key);
        }
    }

    // The event log's "Job loaded" line counts what the machine's run counts (the saw's
    // "10 points, 60000.0 mm" before): a torch path's points and millimetres, the saw's pieces,
    // the crank's strokes.
    void loadNoteCountsTheMachinesWork_data() { machineRows(); }
    void loadNoteCountsTheMachinesWork() {
        QFETCH(QString, id);
        MainWindow w(&cutcell::app::makeRig);
        newJobFor(w, id.toStdString());
        auto loadLine = [&w] {
            for (int r = w.eventLog()->rowCount() - 1; r >= 0; --r)
                if (w.eventLog()->message(r).startsWith("Job loaded: "))
                    return w.eventLog()->message(r);
            return QString();
        };
        QTRY_VERIFY2_WITH_TIMEOUT(w.run()->program() && !loadLine().isEmpty(),
                                  qPrintable(lastLog(w)), 60000);
        const auto program = w.run()->program();
        const QString line = loadLine();
        qInfo("%s: %s", qPrintable(id), qPrintable(line));
        const QString count = QString::number(program->point_count);
        if (program->terms.counts == WorkCount::PathPoints) {
            QVERIFY2(
                line.contains(
                    QString("(%1 points, %2 mm, ").arg(count).arg(program->length_mm, 0, 'f', 1)),
                qPrintable(line));
        } else {
            const QString unit = program->terms.counts == WorkCount::Pieces ? "pieces" : "strokes";
            QVERIFY2(line.contains(QString("(%1 %2").arg(count, unit)), qPrintable(line));
            QVERIFY2(!line.contains("points"), qPrintable(line));
        }
        // Whole phrases, so German too: "Auftrag geladen: ... (10 Stück, 60.000,0 mm insgesamt".
        QVERIFY(CutCell::ui::applyGuiLanguage("de"));
        const QString german = CutCell::ui::engineText(line);
        QVERIFY(CutCell::ui::applyGuiLanguage("en"));
        const char* noun = program->terms.counts == WorkCount::PathPoints ? "Punkte"
                           : program->terms.counts == WorkCount::Pieces   ? "Stück"
                                                                          : "Hübe";
        QVERIFY2(german.startsWith("Auftrag geladen: ") &&
                     german.contains(QString("(%1 %2").arg(count, QString::fromUtf8(noun))),
                 qPrintable(german));
    }

    // E-STOP in the middle of a run on the simulated cell (real time).
    void stopInTheMiddleShowsTheMachinesFigures_data() { machineRows(); }
    void stopInTheMiddleShowsTheMachinesFigures() {
        QFETCH(QString, id);
        MainWindow w(&cutcell::app::makeRig);
        newJobFor(w, id.toStdString());
        w.resize(1280, 720);
        w.show();
        startManually(w);
        const auto program = w.run()->program();
        QVERIFY(program);
        const cutcell::RunTerms terms = program->terms;
        const bool counts = terms.counts != WorkCount::PathPoints;
        // The middle: one piece or stroke made (of several), or an eighth of the path.
        QTRY_VERIFY_WITH_TIMEOUT((counts ? w.run()->bridge()->last().made >= 1
                                         : w.run()->bridge()->last().progress >= 0.125) ||
                                     state(w) != EngineState::Running,
                                 120000);
        QVERIFY2(state(w) == EngineState::Running, cutcell::toString(state(w)));
        QTest::mouseClick(w.controls()->eStopButton(), Qt::LeftButton);
        QTRY_VERIFY2_WITH_TIMEOUT(state(w) == EngineState::EmergencyStop,
                                  cutcell::toString(state(w)), 2000);
        QTRY_VERIFY_WITH_TIMEOUT(!w.progress()->stopText().isEmpty(), 2000);
        cutcell::TrackingReport report;
        cutcell::RunStopPoint stop;
        QTRY_VERIFY_WITH_TIMEOUT(
            w.run()->rig()->engine().lastRunReport(report, nullptr, &stop) && stop.valid, 2000);
        const QString text = w.progress()->stopText();
        qInfo("%s: %s", qPrintable(id), qPrintable(text));
        // For a look: CUTCELL_TEST_SCREENSHOT_DIR=/tmp/shots (under xvfb-run for the real look).
        if (const QString dir = qEnvironmentVariable("CUTCELL_TEST_SCREENSHOT_DIR"); !dir.isEmpty())
            QVERIFY(w.grab().save(dir + "/run_model_" + id + ".png"));
        if (counts) {
            const char* noun = terms.counts == WorkCount::Pieces ? "piece" : "stroke";
            QVERIFY2(stop.made >= 1 && stop.made < stop.point_count,
                     qPrintable(QString("made %1 of %2").arg(stop.made).arg(stop.point_count)));
            // "piece 3 of 10, 2 pieces made": the one in work (1-based) and those made.
            const QRegularExpression figures(
                QString("%1 (\\d+) of (\\d+), (\\d+) %1s? made").arg(noun));
            const auto m = figures.match(text);
            QVERIFY2(m.hasMatch(), qPrintable(text));
            QCOMPARE(m.captured(2).toUInt(), stop.point_count);
            QCOMPARE(m.captured(3).toUInt(), stop.made);
            QVERIFY2(!text.contains(" mm"), qPrintable(text)); // no path millimetres
            // The counter adds what this run made.
            QTRY_VERIFY2_WITH_TIMEOUT(
                w.progress()->cycleText().contains(QString("%1s %2").arg(noun).arg(stop.made),
                                                   Qt::CaseInsensitive),
                qPrintable(w.progress()->cycleText()), 2000);
        } else {
            const QRegularExpression figures("point (\\d+) / (\\d+), ([0-9.]+) of ([0-9.]+) mm");
            const auto m = figures.match(text);
            QVERIFY2(m.hasMatch(), qPrintable(text));
            QCOMPARE(m.captured(2).toUInt(), stop.point_count);
            QVERIFY(std::fabs(m.captured(4).toDouble() - program->length_mm) < 0.06);
            QVERIFY(m.captured(3).toDouble() > 0.1 * program->length_mm);
            QVERIFY(w.progress()->cycleText().contains("Parts 0"));
        }
        // The figures above the stop line are the stop point's too (the last sample shown may
        // predate the last piece or stroke).
        QTRY_COMPARE_WITH_TIMEOUT(w.progress()->pointsText(),
                                  QString("%1 / %2")
                                      .arg(std::min(stop.point_index + 1, stop.point_count))
                                      .arg(stop.point_count),
                                  2000);
        // The engine's stop text names the machine's tool, and so do the lamp and the alarms.
        auto* lamps = w.findChild<CutCell::ui::StateLamps*>();
        QVERIFY(lamps);
        QCOMPARE(lamps->lamp(CutCell::ui::StateLamps::Torch)->text().toLower(),
                 QString::fromStdString(terms.tool));
        const QString tool = QString::fromStdString(terms.tool);
        QVERIFY(!w.alarms()->alarms().empty());
        const QString alarm = w.alarms()->alarms().back().text;
        QVERIFY2(alarm.contains(tool + " off"), qPrintable(alarm));
        if (tool != "torch") QVERIFY2(!alarm.contains("torch"), qPrintable(alarm));
        QCOMPARE(CutCell::ui::AlarmPanel::sourceOf(tool + ": fault 0x0042", terms), tool);
    }
};

QTEST_MAIN(TestRunModel)
#include "test_run_model.moc"
