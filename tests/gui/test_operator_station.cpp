// The operator station as an operator uses it at the cell (issue 12): a layout that holds at
// 1280x720 and 1600x1000 (nothing of the operator column or the forms cut or off screen); a
// position readout equal to the engine's telemetry and jog per axis within the limits; the
// alarm list (raised, acknowledged, cleared, written into the run folder); deliberate stops
// (Abort confirmed by a second press, Release E-STOP and Reset separate, the override back to
// 100 % after a stop, the stop position kept on screen); shortcuts; letters refused visibly.
#include "sim_rig.h"

#include "core/job/default_job.h"
#include "main_window_run.h"
#include "ui/engine_bridge.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/main_window.h"
#include "ui/panels/alarm_panel.h"
#include "ui/panels/control_panel.h"
#include "ui/panels/dro_panel.h"
#include "ui/panels/monitor_views.h"
#include "ui/panels/progress_panel.h"
#include "ui/panels/recovery_panel.h"
#include "ui/run_controller.h"

#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QTabWidget>
#include <QtTest>

#include <cmath>

using cutcell::EngineState;
using CutCell::ui::EngineBridge;
using CutCell::ui::MainWindow;
using CutCell::ui::RecoveryPanel;

namespace {

cutcell::Job shortJob(const std::string& runsDir = "") {
    auto job = cutcell::defaultJob();
    job.cut.speed_mm_s = 40;
    job.cut.ramp_s = 0.2;
    job.sim.duration_s = 3.5;
    job.engine.runs_dir = runsDir;
    return job;
}

// The widgets an operator reads or touches (not the internals of spin boxes, tables...).
bool isOperatorWidget(const QWidget* w) {
    return qobject_cast<const QLabel*>(w) || qobject_cast<const QPushButton*>(w) ||
           qobject_cast<const QAbstractSpinBox*>(w) || qobject_cast<const QComboBox*>(w) ||
           qobject_cast<const QCheckBox*>(w) || qobject_cast<const QSlider*>(w) ||
           qobject_cast<const QProgressBar*>(w) || qobject_cast<const QGroupBox*>(w) ||
           (qobject_cast<const QLineEdit*>(w) &&
            !qobject_cast<const QAbstractSpinBox*>(w->parentWidget()) &&
            !qobject_cast<const QComboBox*>(w->parentWidget()));
}

// Every visible operator widget under `root`: inside its parent's rectangle (a scroll area's
// content may be taller than its viewport, never wider), and at least its minimum size hint
// unless it asks to be ignored.
void checkNothingCut(QWidget* root, const QString& where) {
    for (QWidget* w : root->findChildren<QWidget*>()) {
        if (!w->isVisibleTo(root) || !isOperatorWidget(w)) continue;
        // Cells of a table scroll with the table (the DH table): the table is the frame.
        bool inTable = false;
        for (QWidget* p = w->parentWidget(); p && p != root; p = p->parentWidget())
            inTable = inTable || qobject_cast<QAbstractItemView*>(p);
        if (inTable) continue;
        QWidget* parent = w->parentWidget();
        const QString name =
            QStringLiteral("%1: %2 '%3' (%4)")
                .arg(where, QString::fromLatin1(w->metaObject()->className()), w->objectName(),
                     qobject_cast<QLabel*>(w)
                         ? qobject_cast<QLabel*>(w)->text().left(40)
                         : (qobject_cast<QPushButton*>(w) ? qobject_cast<QPushButton*>(w)->text()
                                                          : QString()));
        // A scroll area's content may be taller than its viewport (it scrolls), never wider.
        auto* area = qobject_cast<QScrollArea*>(parent->parentWidget());
        const bool scrolled = area && area->widget() == w;
        const QRect frame =
            scrolled ? QRect(0, w->y(), parent->width(), w->height()) : parent->rect();
        QVERIFY2(frame.contains(w->geometry()),
                 qPrintable(name + QStringLiteral(" at %1,%2 %3x%4 outside its parent %5x%6")
                                       .arg(w->x())
                                       .arg(w->y())
                                       .arg(w->width())
                                       .arg(w->height())
                                       .arg(parent->width())
                                       .arg(parent->height())));
        if (w->sizePolicy().horizontalPolicy() == QSizePolicy::Ignored) continue;
        const QSize hint = w->minimumSizeHint();
        const QSize min = w->minimumSize();
        const int needW = min.width() > 0 ? min.width() : hint.width();
        const int needH = min.height() > 0 ? min.height() : hint.height();
        QVERIFY2(w->width() >= needW && w->height() >= needH,
                 qPrintable(name + QStringLiteral(" is %1x%2, needs %3x%4")
                                       .arg(w->width())
                                       .arg(w->height())
                                       .arg(needW)
                                       .arg(needH)));
    }
    // Scroll areas scroll down, never sideways: no content wider than its viewport.
    for (QScrollArea* area : root->findChildren<QScrollArea*>()) {
        if (!area->isVisibleTo(root) || !area->widget()) continue;
        QVERIFY2(area->widget()->width() <= area->viewport()->width() &&
                     !area->horizontalScrollBar()->isVisible(),
                 qPrintable(where + QStringLiteral(": %1 content %2 px in a %3 px viewport")
                                        .arg(area->objectName())
                                        .arg(area->widget()->width())
                                        .arg(area->viewport()->width())));
    }
}

// Inside the window's visible area, in window coordinates.
bool onScreen(const QWidget* w, const QWidget* window) {
    const QRect r(w->mapTo(window, QPoint(0, 0)), w->size());
    return window->rect().contains(r);
}

// The window as the operator sees it, with the 3D view's frame (a native GL window that
// QWidget::grab() does not see), as `cutcell --screenshot` saves it.
void saveShot(MainWindow& w, const QString& path) {
    QImage shot = w.grab().toImage();
    w.cellView()->paintFrameInto(shot, &w);
    QVERIFY2(shot.save(path), qPrintable(path));
}

} // namespace

class TestOperatorStation : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void layoutHolds_data() {
        QTest::addColumn<QSize>("size");
        QTest::newRow("1280x720") << QSize(1280, 720);
        QTest::newRow("1600x1000") << QSize(1600, 1000);
    }
    void layoutHolds() {
        QFETCH(QSize, size);
        MainWindow w(&cutcell::app::makeRig);
        w.editor()->setJob(shortJob());
        w.resize(size);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        // The program is loaded: the position readout has its rows.
        QTRY_VERIFY_WITH_TIMEOUT(w.dro()->axisCount() == 6, 60000);
        // A long Start reason keeps its place.
        const int buttonsY = w.controls()->overrideSlider()->mapTo(&w, QPoint()).y();
        w.controls()->setStartBlocked(QString("a long reason. ").repeated(40));
        QCoreApplication::processEvents();
        QCOMPARE(w.controls()->overrideSlider()->mapTo(&w, QPoint()).y(), buttonsY);
        // The window keeps the size asked for (its minimum fits the screen).
        QCOMPARE(w.size(), size);
        QCoreApplication::processEvents();
        checkNothingCut(w.operatorColumn(), QStringLiteral("operator column"));
        // E-STOP and the run buttons are never scrolled away.
        for (QWidget* b : {static_cast<QWidget*>(w.controls()->eStopButton()),
                           static_cast<QWidget*>(w.controls()->startButton()),
                           static_cast<QWidget*>(w.controls()->holdButton()),
                           static_cast<QWidget*>(w.controls()->abortButton()),
                           static_cast<QWidget*>(w.controls()->resetButton()),
                           static_cast<QWidget*>(w.controls()->overrideSlider())})
            QVERIFY2(onScreen(b, &w), qPrintable(b->objectName()));
        // Every parameter tab of the machine: nothing cut, nothing sideways off screen.
        QTabWidget* tabs = w.parameters()->tabs();
        for (int i = 0; i < tabs->count(); ++i) {
            if (!tabs->isTabVisible(i)) continue;
            tabs->setCurrentIndex(i);
            QCoreApplication::processEvents();
            checkNothingCut(tabs->currentWidget(), tabs->tabText(i));
        }
        // The 3D view keeps a usable height.
        QVERIFY2(w.cellView()->height() >= 240,
                 qPrintable(QString::number(w.cellView()->height())));
    }

    void droEqualsTelemetryAndJogs() {
        MainWindow w(&cutcell::app::makeRig);
        w.editor()->setJob(shortJob());
        w.show();
        QTRY_VERIFY_WITH_TIMEOUT(w.controls()->enableButton()->isEnabled() &&
                                     w.controls()->startBlockedReason().contains("Enable"),
                                 60000);
        auto* dro = w.dro();
        const auto program = w.run()->program();
        QVERIFY(program);
        QCOMPARE(dro->axisCount(), program->axis_count);
        for (int i = 0; i < dro->axisCount(); ++i) {
            QCOMPARE(dro->axisName(i), QString::fromStdString(program->axis_names[size_t(i)]));
            QCOMPARE(dro->unit(i),
                     program->axis_linear[size_t(i)] ? QString("mm") : QString("deg"));
        }
        QTest::mouseClick(w.controls()->enableButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Ready, 5000);
        QTest::mouseClick(w.controls()->homeButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(state(w) == EngineState::Ready && w.run()->bridge()->last().homed,
                                 30000);
        QTest::qWait(300);
        // At rest the readout shows the last sample drained (the display follows each tick).
        w.run()->bridge()->poll();
        QTest::qWait(100);
        w.run()->bridge()->poll();
        const auto sample = w.run()->bridge()->last();
        for (int i = 0; i < dro->axisCount(); ++i) {
            const double cmd = dro->toDisplay(i, sample.setpoint[i]);
            const double act = dro->toDisplay(i, sample.actual[i]);
            QCOMPARE(dro->commandedText(i), QString::number(cmd, 'f', dro->kDecimals));
            QCOMPARE(dro->actualText(i), QString::number(act, 'f', dro->kDecimals));
        }
        // Jog axis 1 by +1 deg: the commanded position moves by exactly the step.
        dro->setJogStep(1.0);
        dro->setJogAxis(1);
        const double before = dro->commanded(1);
        QVERIFY(dro->jogButton(+1)->isEnabled());
        QTest::mouseClick(dro->jogButton(+1), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(state(w) == EngineState::Jogging, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Ready, 10000);
        QTest::qWait(200);
        w.run()->bridge()->poll();
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(dro->commanded(1) - (before + 1.0)) < 1e-6, 2000);
        // Continuous: moves while held, stops at the release (on its ramp), no further.
        dro->setJogStep(0);
        QTest::mousePress(dro->jogButton(-1), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(state(w) == EngineState::Jogging, 5000);
        QTest::qWait(300);
        QTest::mouseRelease(dro->jogButton(-1), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Ready, 10000);
        QTest::qWait(200);
        w.run()->bridge()->poll();
        const double stoppedAt = dro->commanded(1);
        QVERIFY2(stoppedAt < before + 1.0 - 1e-3, qPrintable(QString::number(stoppedAt)));
        QVERIFY2(stoppedAt > before + 1.0 - 90, qPrintable(QString::number(stoppedAt)));
        QTest::qWait(300);
        w.run()->bridge()->poll();
        QCOMPARE(dro->commanded(1), stoppedAt);
    }

    void stopsAreDeliberateAndKeepTheStopPosition() {
        QTemporaryDir runs;
        MainWindow w(&cutcell::app::makeRig);
        w.editor()->setJob(shortJob(runs.path().toStdString()));
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        w.controls()->setOverridePercent(150);
        startManually(w);
        QVERIFY(w.controls()->abortButton()->isEnabled());
        // Abort: the first press only asks.
        QTest::mouseClick(w.controls()->abortButton(), Qt::LeftButton);
        QVERIFY(w.controls()->abortArmed());
        QVERIFY(w.controls()->abortButton()->text().contains("again"));
        QTest::qWait(300);
        QCOMPARE(state(w), EngineState::Running);
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->bridge()->last().progress > 0.2, 20000);
        // E-STOP: never waits behind the armed Abort.
        QTest::mouseClick(w.controls()->eStopButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::EmergencyStop, 5000);
        QVERIFY(!w.controls()->abortArmed());
        // The override is back at 100 %, and the log says so.
        QCOMPARE(w.controls()->overridePercent(), 100);
        QTRY_COMPARE_WITH_TIMEOUT(w.run()->bridge()->last().override_fraction, 1.0, 2000);
        // The stop position stays on screen.
        QTest::qWait(300);
        w.run()->bridge()->poll();
        QVERIFY2(w.progress()->stopText().contains("emergency stop"),
                 qPrintable(w.progress()->stopText()));
        QVERIFY(w.progress()->percentText() != QString("0.0 %"));
        QVERIFY(w.progress()->bar()->value() > 0);
        // Release and Reset are two actions: Reset is not offered while pressed.
        QVERIFY(w.controls()->releaseButton()->isEnabled());
        QVERIFY(!w.controls()->resetButton()->isEnabled());
        QTest::mouseClick(w.controls()->releaseButton(), Qt::LeftButton);
        QTest::qWait(200);
        QCOMPARE(state(w), EngineState::EmergencyStop); // released is not reset
        QVERIFY(w.controls()->resetButton()->isEnabled());
        QTest::mouseClick(w.controls()->resetButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Idle, 5000);
        // Still shown after Reset, until the next Start.
        QVERIFY(w.progress()->stopText().contains("emergency stop"));
        QVERIFY(w.progress()->bar()->value() > 0);
        // The alarm list: one E-STOP alarm, past after Reset, acknowledged by the operator,
        // and written into the run folder.
        auto* alarms = w.alarms();
        QCOMPARE(alarms->alarms().size(), size_t(1));
        const auto& a = alarms->alarms().front();
        QVERIFY(a.source.contains("E-STOP"));
        QVERIFY(a.action.contains("Reset"));
        QVERIFY(!a.active);
        QVERIFY(!a.acknowledged);
        QVERIFY(alarms->acknowledgeButton()->isEnabled());
        QTest::mouseClick(alarms->acknowledgeButton(), Qt::LeftButton);
        QVERIFY(alarms->alarms().front().acknowledged);
        const QString dir = QString::fromStdString(w.run()->rig()->engine().lastRunDirectory());
        QVERIFY(!dir.isEmpty());
        QFile f(QDir(dir).filePath("alarms.json"));
        QTRY_VERIFY_WITH_TIMEOUT(f.exists(), 2000);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonArray list = QJsonDocument::fromJson(f.readAll()).array();
        QCOMPARE(list.size(), 1);
        QCOMPARE(list[0].toObject()["acknowledged"].toBool(), true);
        QCOMPARE(list[0].toObject()["text"].toString(), a.text);
        QString err;
        QVERIFY2(alarms->exportCsv(runs.filePath("alarms.csv"), &err), qPrintable(err));
        // For the docs: CUTCELL_SHOT_DIR=docs saves the window with its alarm list.
        if (qEnvironmentVariableIsSet("CUTCELL_SHOT_DIR"))
            saveShot(w, QDir(qEnvironmentVariable("CUTCELL_SHOT_DIR")).filePath("alarms.png"));
        // The run log's summary has the stop position too.
        QFile summary(QDir(dir).filePath("summary.json"));
        QTRY_VERIFY_WITH_TIMEOUT(summary.exists(), 2000);
        QVERIFY(summary.open(QIODevice::ReadOnly));
        const QJsonObject stop =
            QJsonDocument::fromJson(summary.readAll()).object()["stop"].toObject();
        QVERIFY(stop["progress"].toDouble() > 0.2);
        QVERIFY(stop["length_mm"].toDouble() > 0);
    }

    void abortNeedsTwoPressesAndKeysWork() {
        MainWindow w(&cutcell::app::makeRig);
        w.editor()->setJob(shortJob());
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTRY_VERIFY_WITH_TIMEOUT(w.controls()->enableButton()->isEnabled() &&
                                     w.controls()->startBlockedReason().contains("Enable"),
                                 60000);
        QTest::mouseClick(w.controls()->enableButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Ready, 5000);
        QTest::mouseClick(w.controls()->homeButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(state(w) == EngineState::Ready &&
                                     w.run()->bridge()->last().homed &&
                                     w.controls()->startButton()->isEnabled(),
                                 30000);
        // Start by its key.
        QTest::keyClick(&w, Qt::Key_F5);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Running, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->bridge()->last().progress > 0.05, 20000);
        // Override + by its key.
        QTest::keyClick(&w, Qt::Key_F10);
        QCOMPARE(w.controls()->overridePercent(), 110);
        QTest::keyClick(&w, Qt::Key_F9);
        QTest::keyClick(&w, Qt::Key_F9);
        QCOMPARE(w.controls()->overridePercent(), 90);
        // Feed hold, Resume by their keys.
        QTest::keyClick(&w, Qt::Key_F6);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Paused, 5000);
        QTest::keyClick(&w, Qt::Key_F7);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Running, 5000);
        // Abort by its key: once asks, twice aborts.
        QTest::keyClick(&w, Qt::Key_F8);
        QTest::qWait(300);
        QCOMPARE(state(w), EngineState::Running);
        QTest::keyClick(&w, Qt::Key_F8);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Ready, 5000);
        QVERIFY(w.progress()->stopText().contains("abort"));
        QCOMPARE(w.controls()->overridePercent(), 100);
        // Help lists the keys.
        const QString help = CutCell::ui::ControlPanel::keysHelp();
        for (const char* k : {"F1", "F5", "F6", "F7", "F8", "F9", "F10"})
            QVERIFY2(help.contains(k), k);
    }

    // Cut recovery: after an E-STOP the panel offers the rest of the cut from the stop point
    // (minus the lead-in) once the machine is Ready and homed; the resumed run approaches that
    // point, lights the torch there and completes the cut.
    void cutRecoveryResumesFromTheStopPointAndCompletes() {
        MainWindow w(&cutcell::app::makeRig);
        w.editor()->setJob(shortJob());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w)); // also under Xvfb without a window manager
        std::vector<cutcell::TelemetrySample> lit;
        QStringList events;
        connect(w.run()->bridge(), &EngineBridge::samples, &w,
                [&](const std::vector<cutcell::TelemetrySample>& batch) {
                    for (const auto& t : batch)
                        if (t.torch_on) lit.push_back(t);
                });
        connect(w.run()->bridge(), &EngineBridge::event, &w,
                [&](const cutcell::EngineEvent& e) { events << QString::fromUtf8(e.text.data()); });
        startManually(w);
        RecoveryPanel* rec = w.recovery();
        QVERIFY(!rec->resumeButton()->isEnabled()); // nothing stopped yet
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->bridge()->last().progress > 0.3, 30000);
        QTest::mouseClick(w.controls()->eStopButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::EmergencyStop, 5000);
        // The stop point is known; recovery is refused with the reason until Ready and homed.
        QTRY_VERIFY_WITH_TIMEOUT(rec->resumePathTime() > 0, 2000);
        QVERIFY(!rec->resumeButton()->isEnabled());
        QVERIFY2(rec->reason().contains("Ready"), qPrintable(rec->reason()));
        const auto program = w.run()->program();
        QVERIFY(program);
        const double leadIn_s =
            rec->leadInField()->value() * program->cut_time_s / program->length_mm;
        const double stopTau = rec->resumePathTime() + leadIn_s;
        QTest::mouseClick(w.controls()->releaseButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(w.controls()->resetButton()->isEnabled(), 2000);
        QTest::mouseClick(w.controls()->resetButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Idle, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(w.controls()->enableButton()->isEnabled(), 5000);
        QTest::mouseClick(w.controls()->enableButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Ready, 5000);
        QVERIFY2(rec->reason().contains("Home"), qPrintable(rec->reason()));
        QTest::mouseClick(w.controls()->homeButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(state(w) == EngineState::Ready && w.run()->bridge()->last().homed,
                                 30000);
        QTRY_VERIFY2_WITH_TIMEOUT(rec->resumeButton()->isEnabled(), qPrintable(rec->reason()),
                                  2000);
        if (qEnvironmentVariableIsSet("CUTCELL_SHOT_DIR"))
            saveShot(w,
                     QDir(qEnvironmentVariable("CUTCELL_SHOT_DIR")).filePath("cut_recovery.png"));
        lit.clear();
        QTest::mouseClick(rec->resumeButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Completed, 60000);
        QVERIFY2(events.join('\n').contains("cut recovery from path time"),
                 qPrintable(events.join('\n')));
        // The torch was lit first at the recovery point (before the stop point: the lead-in
        // re-cuts a little), and the resumed run reached the end of the path.
        QVERIFY(!lit.empty());
        const double firstTau = lit.front().progress * program->cut_time_s;
        QVERIFY2(std::abs(firstTau - (stopTau - leadIn_s)) < 0.01,
                 qPrintable(QString("torch lit at %1 s, recovery point %2 s")
                                .arg(firstTau)
                                .arg(stopTau - leadIn_s)));
        QVERIFY(firstTau < stopTau);
        QCOMPARE(w.run()->bridge()->last().progress, 1.0);
        cutcell::TrackingReport report;
        std::string outcome;
        QVERIFY(w.run()->rig()->engine().lastRunReport(report, &outcome));
        QCOMPARE(QString::fromStdString(outcome), QString("completed"));
        // Resumed from before the stop point: the whole path was cut, the part counts.
        QTRY_COMPARE_WITH_TIMEOUT(w.run()->partsCompleted(), 1, 2000);
        QVERIFY(w.run()->unconfirmedPart().isEmpty());
    }

    void approachShowsProgressAndCyclesAreCounted() {
        MainWindow w(&cutcell::app::makeRig);
        w.editor()->setJob(shortJob());
        w.show();
        startManually(w);
        // Approach: the cut's progress is 0, the detail line tells how far the approach is.
        QTRY_VERIFY_WITH_TIMEOUT(w.progress()->stopText().contains("Approach") ||
                                     w.progress()->stopText().contains("first cut point"),
                                 5000);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Completed, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->partsCompleted() == 1, 2000);
        QVERIFY(w.run()->lastCycleS() > 1.0);
        QVERIFY2(w.progress()->cycleText().contains("Parts 1"),
                 qPrintable(w.progress()->cycleText()));
        // A new job starts its own count.
        QVERIFY(w.newJob("pipe_robot_6axis")); // the default job's machine
        QCOMPARE(w.run()->partsCompleted(), 0);
    }

    void lettersInNumberFieldsAreRefusedVisibly() {
        MainWindow w(nullptr);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        w.parameters()->revealField("cut.speed_mm_s");
        auto* box = qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("cut.speed_mm_s"));
        QVERIFY(box);
        box->setFocus();
        QTRY_VERIFY(box->hasFocus());
        box->selectAll();
        QTest::keyClicks(box, "4x0abc");
        QCOMPARE(box->value(), 40.0);
        QVERIFY(box->property("refused").toBool());
        const QString why = box->property("refusedInput").toString();
        QVERIFY2(why.contains("'c'") && why.contains("cut.speed_mm_s"), qPrintable(why));
        QTRY_VERIFY_WITH_TIMEOUT(!box->property("refused").toBool(), 3000);
    }
};

QTEST_MAIN(TestOperatorStation)
#include "test_operator_station.moc"
