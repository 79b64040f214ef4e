// Runs on the simulated cell through the main window, as the operator would: a full run
// reaches 100 % and Completed with data in the plots; EMERGENCY STOP (button and F1 from a
// focused field) latches, turns the torch off and disables the drives, and Release E-STOP then
// Reset clear it;
// feed hold stops the progress and Resume continues the run to its end.
#include "sim_rig.h"

#include "core/job/default_job.h"
#include "main_window_run.h"
#include "plots/tracking_plots_widget.h"
#include "ui/engine_bridge.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/main_window.h"
#include "ui/panels/control_panel.h"
#include "ui/panels/event_log_panel.h"
#include "ui/panels/monitor_views.h"
#include "ui/panels/progress_panel.h"
#include "ui/panels/state_lamps.h"
#include "ui/run_controller.h"

#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QtTest>

using cutcell::EngineState;
using CutCell::ui::MainWindow;
using CutCell::ui::StateLamps;

namespace {

// A short cut (about 3 s) so that real-time runs stay quick.
cutcell::Job shortJob() {
    auto job = cutcell::defaultJob();
    job.cut.speed_mm_s = 40;
    job.cut.ramp_s = 0.2;
    job.sim.duration_s = 3.5;
    job.engine.runs_dir = "";
    return job;
}

// Waits until the GUI has a sample from at least `seconds` of engine time after its current
// one: "nothing changed" is then checked over that many cycles however slow the machine is
// (a fixed qWait checks fewer cycles, or none, when the machine is slow).
void waitForEngineTime(const MainWindow& w, double seconds) {
    const double from = w.run()->bridge()->last().time_s;
    QTRY_VERIFY_WITH_TIMEOUT(w.run()->bridge()->last().time_s >= from + seconds, 30000);
}

} // namespace

class TestGuiRun : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void fullRunReachesCompletedWithPlots() {
        MainWindow w(&cutcell::app::makeRig);
        w.run()->setClockMode(cutcell::ClockMode::AsFastAsPossible);
        auto job = cutcell::defaultJob();
        job.engine.runs_dir = "";
        w.editor()->setJob(job);
        w.show();
        QString why;
        QVERIFY2(autoRunCompletes(w, 180000, &why), qPrintable(why));
        w.run()->bridge()->poll();
        QCOMPARE(w.progress()->percentText(), QString("100.0 %"));
        QCOMPARE(w.progress()->bar()->value(), w.progress()->bar()->maximum());
        const auto& last = w.run()->bridge()->last();
        QVERIFY(last.point_count > 0);
        QCOMPARE(w.progress()->pointsText(),
                 QString("%1 / %1").arg(last.point_count)); // the last point of the path
        QVERIFY(!last.torch_on);
        // Both plots got data (joint errors and Cartesian errors come in the same samples).
        QVERIFY(w.plots()->samplesAppended() > 0);
        auto* plots = w.plots()->plots();
        QVERIFY(plots->sampleCount() > 0);
        plots->replotNow();
        QVERIFY(plots->plottedPointCount() > 0);
        QTemporaryDir dir;
        QString err;
        QVERIFY2(plots->exportCsv(dir.filePath("errors.csv"), &err), qPrintable(err));
        QFile csv(dir.filePath("errors.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        QVERIFY(csv.readAll().count('\n') > 10);
        QVERIFY(w.lamps()->lamp(StateLamps::Ready)->isLit());
    }

    void emergencyStopLatchesAndResetClears_data() {
        QTest::addColumn<bool>("byShortcut");
        QTest::newRow("button") << false;
        QTest::newRow("F1 from a field") << true;
    }

    void emergencyStopLatchesAndResetClears() {
        QFETCH(bool, byShortcut);
        MainWindow w(&cutcell::app::makeRig);
        w.editor()->setJob(shortJob());
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        startManually(w);
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->bridge()->last().torch_on, 10000);
        QVERIFY(w.lamps()->lamp(StateLamps::Torch)->isLit());

        if (byShortcut) {
            // Parameters are locked while the cut runs; the event log can hold the focus.
            QWidget* field = w.eventLog()->table();
            field->setFocus();
            QTRY_VERIFY(field->hasFocus());
            QTest::keyClick(field, Qt::Key_F1);
        } else {
            QTest::mouseClick(w.controls()->eStopButton(), Qt::LeftButton);
        }
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::EmergencyStop, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!w.run()->bridge()->last().torch_on, 2000);
        QVERIFY(w.lamps()->lamp(StateLamps::EStop)->isLit());
        QVERIFY(!w.lamps()->lamp(StateLamps::Torch)->isLit());
        QTRY_VERIFY_WITH_TIMEOUT(drivesDisabled(w), 2000);
        // Latched: it stays so, Start is blocked, Reset is offered.
        waitForEngineTime(w, 0.3);
        if (QTest::currentTestFailed()) return;
        QCOMPARE(state(w), EngineState::EmergencyStop);
        QVERIFY(!w.controls()->startButton()->isEnabled());
        QVERIFY(w.controls()->startBlockedReason().contains("EMERGENCY STOP"));
        QVERIFY(w.controls()->eStopButton()->isEnabled());
        // Release and Reset are two actions.
        QVERIFY(!w.controls()->resetButton()->isEnabled());
        QVERIFY(w.controls()->releaseButton()->isEnabled());
        QTest::mouseClick(w.controls()->releaseButton(), Qt::LeftButton);
        QVERIFY(w.controls()->resetButton()->isEnabled());

        QTest::mouseClick(w.controls()->resetButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Idle, 5000);
        QVERIFY(!w.lamps()->lamp(StateLamps::EStop)->isLit());
        QVERIFY(w.controls()->enableButton()->isEnabled());
        QVERIFY(w.controls()->startBlockedReason().contains("Enable"));
    }

    void feedHoldAndResumeContinueTheRun() {
        MainWindow w(&cutcell::app::makeRig);
        w.editor()->setJob(shortJob());
        w.show();
        startManually(w);
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->bridge()->last().progress > 0.15, 10000);
        QVERIFY(w.controls()->holdButton()->isEnabled());
        QTest::mouseClick(w.controls()->holdButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Paused, 5000);
        QVERIFY(w.lamps()->lamp(StateLamps::Paused)->isLit());
        // Stopped on the path: the progress no longer moves. The state comes from the newest
        // sample, so that sample is already Paused (the deceleration has ended).
        QCOMPARE(w.run()->bridge()->last().state, EngineState::Paused);
        const double held = w.run()->bridge()->last().progress;
        waitForEngineTime(w, 0.4);
        if (QTest::currentTestFailed()) return;
        QCOMPARE(w.run()->bridge()->last().progress, held);
        QVERIFY(held < 1.0);
        QVERIFY(w.controls()->resumeButton()->isEnabled());
        QTest::mouseClick(w.controls()->resumeButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Running, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Completed, 30000);
        w.run()->bridge()->poll();
        QCOMPARE(w.progress()->percentText(), QString("100.0 %"));
    }

  private:
    static bool drivesDisabled(const MainWindow& w) {
        for (auto s : w.run()->bridge()->last().drive_states)
            if (s == cutcell::DriveState::Enabled || s == cutcell::DriveState::Enabling)
                return false;
        return true;
    }

    // Enable, Home and Start with the buttons, waiting for each state like an operator.
    static void startManually(MainWindow& w) {
        QTRY_VERIFY_WITH_TIMEOUT(w.controls()->enableButton()->isEnabled() &&
                                     w.controls()->startBlockedReason().contains("Enable"),
                                 60000);
        QTest::mouseClick(w.controls()->enableButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Ready, 5000);
        QTest::mouseClick(w.controls()->homeButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(state(w) == EngineState::Ready && w.run()->bridge()->last().homed,
                                 30000);
        QTRY_VERIFY2_WITH_TIMEOUT(w.controls()->startButton()->isEnabled(),
                                  qPrintable(w.controls()->startBlockedReason()), 2000);
        QTest::mouseClick(w.controls()->startButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Running, 10000);
    }
};

QTEST_MAIN(TestGuiRun)
#include "test_gui_run.moc"
