// Issue 21's defects 8, 13, 14 and 15, one case each (each failed on main at 85d171e):
//  8. No stale figures: after an Abort the remaining time is not a frozen countdown; after
//     File -> New the previous run's stop line, totals, From point and plot data are gone.
// 13. Save never overwrites a job shipped with CutCell (it saves a copy in the operator's job
//     folder); Save As and the exports open there with a file name proposed from the job.
// 14. The engine state reads as words ("Emergency stop", not "EmergencyStop").
// 15. Every operator action has a key (Enable F2, Home F3, Reset F4, Release Ctrl+Shift+F1,
//     Acknowledge F12; the E-STOP's F1 untouched), and Start after an Abort waits for Home (a
//     cut recovery may still resume).
#include "sim_rig.h"

#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "main_window_run.h"
#include "ui/engine_bridge.h"
#include "ui/file_places.h"
#include "ui/forms/job_editor.h"
#include "ui/job_document.h"
#include "ui/main_window.h"
#include "ui/panels/alarm_panel.h"
#include "ui/panels/control_panel.h"
#include "ui/panels/monitor_views.h"
#include "ui/panels/progress_panel.h"
#include "ui/panels/recovery_panel.h"
#include "ui/run_controller.h"

#include <QCryptographicHash>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

using CutCell::ui::MainWindow;

namespace {

QByteArray fileHash(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256);
}

// The robot's default job, short, with its run logs in `runs`.
cutcell::Job shortRobotJob(const QTemporaryDir& runs) {
    auto job = cutcell::defaultJob();
    job.cut.speed_mm_s = 40;
    job.cut.ramp_s = 0.2;
    job.sim.duration_s = 3.5;
    job.engine.runs_dir = runs.path().toStdString();
    return job;
}

// A key as the operator presses it: to whatever has the focus.
void press(MainWindow& w, Qt::Key key, Qt::KeyboardModifiers mods = Qt::NoModifier) {
    QWidget* to = QApplication::focusWidget();
    QTest::keyClick(to ? to : static_cast<QWidget*>(&w), key, mods);
}

// A running cut aborted (two presses of Abort) part way along the path.
void abortPartWay(MainWindow& w) {
    QTRY_VERIFY_WITH_TIMEOUT(w.run()->bridge()->last().progress > 0.2, 30000);
    QTest::mouseClick(w.controls()->abortButton(), Qt::LeftButton);
    QTest::mouseClick(w.controls()->abortButton(), Qt::LeftButton);
    QTRY_VERIFY2_WITH_TIMEOUT(state(w) == cutcell::EngineState::Ready, cutcell::toString(state(w)),
                              10000);
    QTRY_VERIFY2_WITH_TIMEOUT(w.progress()->stopText().contains("abort"),
                              qPrintable(w.progress()->stopText()), 5000);
}

// The window on screen with the short robot job (run logs in `runs`).
void showShortRobotJob(MainWindow& w, const QTemporaryDir& runs) {
    w.editor()->setJob(shortRobotJob(runs));
    w.show();
}

// Enable, Home, Start by hand, then the abort.
void startAndAbort(MainWindow& w) {
    startManually(w);
    abortPartWay(w);
}

} // namespace

class TestOperatorDefectsMore : public QObject {
    Q_OBJECT

    QTemporaryDir home_; // the operator's job and export folders

  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(home_.isValid());
        QDir(home_.path()).mkpath("jobs");
        QDir(home_.path()).mkpath("exports");
        QSettings().setValue("files/jobs_dir", home_.filePath("jobs"));
        QSettings().setValue("files/exports_dir", home_.filePath("exports"));
    }
    void cleanup() { CutCell::ui::setSavePathPrompt({}); }

    void defect08_noStaleFiguresAfterAbortOrNew() {
        MainWindow w(&cutcell::app::makeRig);
        w.setSavePrompt([] { return int(QMessageBox::Discard); });
        QTemporaryDir runs;
        w.editor()->setJob(shortRobotJob(runs));
        w.show();
        startAndAbort(w);
        // The run is over: no countdown frozen at the abort.
        QCOMPARE(w.progress()->remainingText(), QStringLiteral("--"));
        QTRY_VERIFY_WITH_TIMEOUT(w.recovery()->pointField()->value() > 1, 3000);
        // Another machine's job: nothing of the robot's run stays.
        QVERIFY(w.newJob("flying_saw"));
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->program() &&
                                     w.run()->program()->terms.counts == cutcell::WorkCount::Pieces,
                                 60000);
        QVERIFY2(w.progress()->stopText().isEmpty(), qPrintable(w.progress()->stopText()));
        QVERIFY2(w.progress()->pointsText().startsWith("0 / "),
                 qPrintable(w.progress()->pointsText()));
        QVERIFY2(w.progress()->remainingText() != "--", "the new job's planned time is shown");
        QCOMPARE(w.recovery()->pointField()->value(), 1);
        QCOMPARE(w.recovery()->resumePathTime(), 0.0);
        QCOMPARE(w.plots()->samplesAppended(), std::uint64_t(0));
    }

    void defect13_saveNeverOverwritesAShippedJob() {
        MainWindow w(nullptr);
        const QString shipped =
            QStringLiteral(CUTCELL_SOURCE_DIR "/resources/jobs/flying_saw_job.json");
        const QByteArray before = fileHash(shipped);
        QVERIFY(!before.isEmpty());
        QString error;
        QVERIFY2(w.openJob(shipped, &error), qPrintable(error));
        auto job = w.editor()->job();
        job.description = "changed by the operator";
        w.editor()->setJob(job);
        QString proposed;
        const QString copy = home_.filePath("jobs/my_saw.json");
        CutCell::ui::setSavePathPrompt([&](const QString&, const QString& p, const QString&) {
            proposed = p;
            return copy;
        });
        QVERIFY(w.save()); // Ctrl+S
        QCOMPARE(fileHash(shipped), before);
        QVERIFY2(proposed.startsWith(home_.filePath("jobs") + "/") &&
                     proposed.endsWith("flying_saw_job_copy.json"),
                 qPrintable(proposed));
        QCOMPARE(w.document()->path(), copy);
        QFile saved(copy);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QVERIFY(saved.readAll().contains("changed by the operator"));
        // The copy is the operator's own: Save writes it in place, no dialog.
        proposed.clear();
        QVERIFY(w.save());
        QVERIFY(proposed.isEmpty());
    }

    void defect13_exportsProposeAFileName() {
        MainWindow w(nullptr);
        QString error;
        QVERIFY2(
            w.openJob(QStringLiteral(CUTCELL_SOURCE_DIR "/resources/jobs/profile_cutter_job.json"),
                      &error),
            qPrintable(error));
        QStringList proposals;
        CutCell::ui::setSavePathPrompt([&](const QString&, const QString& p, const QString&) {
            proposals << p;
            return QString(); // cancelled: nothing written
        });
        const auto actions = w.findChildren<QAction*>();
        int triggered = 0;
        for (QAction* a : actions) {
            const QString t = a->text();
            if (!t.startsWith("Export") && !t.contains("tiles") && !t.contains("Single sheet"))
                continue;
            if (a->menu()) continue;
            a->trigger();
            ++triggered;
        }
        QVERIFY2(triggered >= 4, qPrintable(QString::number(triggered)));
        QCOMPARE(proposals.size(), triggered);
        for (const QString& p : proposals) {
            const QFileInfo f(p);
            QVERIFY2(f.absolutePath() == home_.filePath("exports") &&
                         f.fileName().startsWith("profile_cutter_job") && !f.suffix().isEmpty(),
                     qPrintable(p));
        }
        QVERIFY2(proposals.filter("_plots.png").size() == 2 && // the menu and the plots toolbar
                     proposals.filter("_alarms.csv").size() == 1,
                 qPrintable(proposals.join('\n')));
    }

    void defect13_fileStems() {
        using CutCell::ui::fileStem;
        QCOMPARE(fileStem({}, "Flying saw: demo/1"), QStringLiteral("Flying_saw_demo_1"));
        QCOMPARE(fileStem({}, "  "), QStringLiteral("job"));
        QCOMPARE(fileStem("/x/y/a.b.json", "ignored"), QStringLiteral("a.b"));
        QCOMPARE(CutCell::ui::filterSuffix("G-code (*.ngc *.nc)"), QStringLiteral(".ngc"));
    }

    void defect14_statesReadAsWords() {
        MainWindow w(&cutcell::app::makeRig);
        QTemporaryDir runs;
        showShortRobotJob(w, runs);
        startManually(w);
        QTest::mouseClick(w.controls()->eStopButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), cutcell::EngineState::EmergencyStop, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(w.progress()->stateText() == "Emergency stop", 3000);
        const auto labels = w.findChildren<QLabel*>();
        for (const QLabel* l : labels)
            QVERIFY2(!l->text().contains("EmergencyStop"), qPrintable(l->text()));
    }

    void defect15_everyOperatorActionHasAKey() {
        MainWindow w(&cutcell::app::makeRig);
        QTemporaryDir runs;
        showShortRobotJob(w, runs);
        QVERIFY(QTest::qWaitForWindowActive(&w));
        const QString keys = CutCell::ui::ControlPanel::keysHelp();
        for (const char* k : {"F1:", "F2: Enable", "F3: Home", "F4: Reset",
                              "Ctrl+Shift+F1: Release", "F12: acknowledge"})
            QVERIFY2(keys.contains(QLatin1String(k)), qPrintable(keys));
        // The rig and the program are there when Start waits for Enable only.
        QTRY_VERIFY_WITH_TIMEOUT(w.controls()->enableButton()->isEnabled() &&
                                     w.controls()->startBlockedReason().contains("Enable"),
                                 60000);
        press(w, Qt::Key_F2);
        QTRY_VERIFY2_WITH_TIMEOUT(state(w) == cutcell::EngineState::Ready, qPrintable(lastLog(w)),
                                  5000);
        press(w, Qt::Key_F3);
        QTRY_VERIFY_WITH_TIMEOUT(
            state(w) == cutcell::EngineState::Ready && w.run()->bridge()->last().homed, 30000);
        press(w, Qt::Key_F1);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), cutcell::EngineState::EmergencyStop, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(w.alarms()->unacknowledgedCount() > 0, 3000);
        press(w, Qt::Key_F12);
        QCOMPARE(w.alarms()->unacknowledgedCount(), 0);
        press(w, Qt::Key_F4); // refused: still pressed
        QCOMPARE(state(w), cutcell::EngineState::EmergencyStop);
        press(w, Qt::Key_F1, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY_WITH_TIMEOUT(w.controls()->resetButton()->isEnabled(), 3000);
        press(w, Qt::Key_F4);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), cutcell::EngineState::Idle, 5000);
    }

    void defect15_startAfterAnAbortWaitsForHome() {
        MainWindow w(&cutcell::app::makeRig);
        QTemporaryDir runs;
        showShortRobotJob(w, runs);
        startAndAbort(w);
        QTRY_VERIFY_WITH_TIMEOUT(w.controls()->startBlockedReason().contains("Home"), 3000);
        QVERIFY(!w.controls()->startButton()->isEnabled());
        // The cut recovery still resumes from the stop without homing.
        QTRY_VERIFY_WITH_TIMEOUT(w.recovery()->resumeButton()->isEnabled(), 3000);
        QTest::mouseClick(w.recovery()->resumeButton(), Qt::LeftButton);
        QTRY_VERIFY2_WITH_TIMEOUT(state(w) == cutcell::EngineState::Running,
                                  cutcell::toString(state(w)), 10000);
        QTRY_VERIFY2_WITH_TIMEOUT(state(w) == cutcell::EngineState::Completed,
                                  cutcell::toString(state(w)), 60000);
        // A fresh abort, then Home: Start is back.
        QTest::mouseClick(w.controls()->homeButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(
            state(w) == cutcell::EngineState::Ready && w.run()->bridge()->last().homed, 30000);
        QTRY_VERIFY2_WITH_TIMEOUT(w.controls()->startButton()->isEnabled(),
                                  qPrintable(w.controls()->startBlockedReason()), 5000);
        QTest::mouseClick(w.controls()->startButton(), Qt::LeftButton);
        abortPartWay(w);
        QVERIFY(!w.controls()->startButton()->isEnabled());
        QTest::mouseClick(w.controls()->homeButton(), Qt::LeftButton);
        QTRY_VERIFY2_WITH_TIMEOUT(w.controls()->startButton()->isEnabled(),
                                  qPrintable(w.controls()->startBlockedReason()), 30000);
    }
};

QTEST_MAIN(TestOperatorDefectsMore)
#include "test_operator_defects_more.moc"
