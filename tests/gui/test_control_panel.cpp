// The control panel: the EMERGENCY STOP is enabled in every state and its shortcut works from
// a focused field; buttons follow the engine state; the override slider reports fractions.
#include "core/job/default_job.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/main_window.h"
#include "ui/panels/control_panel.h"
#include "ui/panels/event_log_panel.h"
#include "ui/panels/progress_panel.h"
#include "ui/panels/run_words.h"
#include "ui/panels/state_lamps.h"

#include <QDialog>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSlider>
#include <QtTest>

using cutcell::EngineState;
using CutCell::ui::ControlPanel;

class TestControlPanel : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void eStopEnabledInEveryState() {
        ControlPanel p;
        for (int s = 0; s <= static_cast<int>(EngineState::Fault); ++s) {
            p.setState(static_cast<EngineState>(s), false);
            p.setStartBlocked(s % 2 ? QString("blocked") : QString());
            QVERIFY(p.eStopButton()->isEnabled());
        }
        QVERIFY(p.eStopButton()->text().contains(ControlPanel::kEStopKey));
    }

    void eStopShortcutFromAFocusedField() {
        CutCell::ui::MainWindow w(nullptr);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QSignalSpy spy(w.controls(), &ControlPanel::emergencyStopRequested);
        for (const char* key : {"cut.speed_mm_s", "name"}) {
            QWidget* field = w.parameters()->fieldFor(key);
            w.parameters()->revealField(key);
            field->setFocus();
            QTRY_VERIFY(field->hasFocus());
            QTest::keyClick(QApplication::focusWidget(), Qt::Key_F1);
        }
        QCOMPARE(spy.count(), 2);
        // The field did not take the key as input.
        QCOMPARE(w.editor()->job().name, cutcell::defaultJob().name);
        // And the button.
        QTest::mouseClick(w.controls()->eStopButton(), Qt::LeftButton);
        QCOMPARE(spy.count(), 3);
    }

    void eStopShortcutInsideAModalDialog() {
        CutCell::ui::MainWindow w(nullptr);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QSignalSpy spy(w.controls(), &ControlPanel::emergencyStopRequested);
        QDialog dialog(&w);
        auto* edit = new QLineEdit(&dialog);
        dialog.setModal(true);
        dialog.open(); // modal, as a file dialog or a question would be
        QVERIFY(QTest::qWaitForWindowActive(&dialog));
        edit->setFocus();
        QTRY_VERIFY(edit->hasFocus());
        QTest::keyClick(edit, Qt::Key_F1);
        QCOMPARE(spy.count(), 1);
        QVERIFY(edit->text().isEmpty());
        dialog.close();
    }

    void buttonsFollowState() {
        ControlPanel p;
        p.setStartBlocked({});
        p.setState(EngineState::Running, true);
        QVERIFY(p.holdButton()->isEnabled());
        QVERIFY(!p.resumeButton()->isEnabled());
        QVERIFY(p.abortButton()->isEnabled());
        // Abort is confirmed by a second press, not by a dialog.
        QSignalSpy abort(&p, &ControlPanel::abortRequested);
        p.abortButton()->click();
        QCOMPARE(abort.count(), 0);
        QVERIFY(p.abortArmed());
        p.abortButton()->click();
        QCOMPARE(abort.count(), 1);
        QVERIFY(!p.abortArmed());
        p.setState(EngineState::Paused, true);
        QVERIFY(!p.holdButton()->isEnabled());
        QVERIFY(p.resumeButton()->isEnabled());
        p.setState(EngineState::EmergencyStop, true);
        // Pressed: only Release is offered; released: only Reset (two deliberate actions).
        p.setEStopPressed(true);
        QVERIFY(p.releaseButton()->isEnabled());
        QVERIFY(!p.resetButton()->isEnabled());
        p.setEStopPressed(false);
        QVERIFY(!p.releaseButton()->isEnabled());
        QVERIFY(p.resetButton()->isEnabled());
        QVERIFY(!p.enableButton()->isEnabled());
        p.setState(EngineState::Idle, false);
        QVERIFY(p.enableButton()->isEnabled());
        p.setStartBlocked("drives disabled");
        QVERIFY(!p.startButton()->isEnabled());
    }

    void overrideSliderReportsFraction() {
        ControlPanel p;
        QSignalSpy spy(&p, &ControlPanel::overrideChanged);
        p.overrideSlider()->setValue(80);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toDouble(), 0.8);
    }

    void lampsShowState() {
        CutCell::ui::StateLamps lamps;
        lamps.setState(EngineState::EmergencyStop);
        QVERIFY(lamps.lamp(CutCell::ui::StateLamps::EStop)->isLit());
        QVERIFY(!lamps.lamp(CutCell::ui::StateLamps::Running)->isLit());
        lamps.setState(EngineState::Running);
        QVERIFY(!lamps.lamp(CutCell::ui::StateLamps::EStop)->isLit());
        QVERIFY(lamps.lamp(CutCell::ui::StateLamps::Running)->isLit());
    }

    void faultEventsSayHowToClear() {
        CutCell::ui::EventLogPanel log;
        cutcell::EngineEvent e;
        e.severity = cutcell::Severity::Error;
        e.from = EngineState::Running;
        e.to = EngineState::Fault;
        const char msg[] = "following error on axis 2: 2.5 deg > limit 2 deg";
        std::copy(std::begin(msg), std::end(msg), e.text.begin());
        log.addEngineEvent(e);
        QCOMPARE(log.rowCount(), 1);
        QVERIFY(log.message(0).contains("following error on axis 2"));
        QVERIFY(log.message(0).contains("Reset"));
        for (int i = 0; i < CutCell::ui::EventLogPanel::kMaxRows + 10; ++i)
            log.add(cutcell::Severity::Info, QString::number(i));
        QCOMPARE(log.rowCount(), CutCell::ui::EventLogPanel::kMaxRows);
    }

    void eventTransitionsUseTheStatesWords() {
        // "Running -> Emergency stop" as the lamps and the state label say it (in German
        // "Läuft -> NOT-HALT"), not the enum's "EmergencyStop" (issue 21, defect 14).
        CutCell::ui::EventLogPanel log;
        cutcell::EngineEvent e;
        e.from = EngineState::Running;
        e.to = EngineState::EmergencyStop;
        log.addEngineEvent(e);
        QCOMPARE(log.rowCount(), 1);
        QVERIFY2(log.message(0).contains(CutCell::ui::stateWord(EngineState::Running) + " -> " +
                                         CutCell::ui::stateWord(EngineState::EmergencyStop)),
                 qPrintable(log.message(0)));
        QVERIFY2(!log.message(0).contains("EmergencyStop"), qPrintable(log.message(0)));
    }

    void durationFormat() {
        QCOMPARE(CutCell::ui::ProgressPanel::formatDuration(0), QString("00:00.0"));
        QCOMPARE(CutCell::ui::ProgressPanel::formatDuration(75.25), QString("01:15.3"));
    }
};

QTEST_MAIN(TestControlPanel)
#include "test_control_panel.moc"
