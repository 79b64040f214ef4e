// The 2-axis profile cutter (seed 002) in the operator station: the job file selects the
// machine; the simulated cell (A + X steppers, torch) runs it to Completed with progress and
// both plots fed on two axes (A in deg, X in mm); EMERGENCY STOP latches and turns the torch
// off; feed hold holds the progress; a job whose cut leaves the X travel blocks Start with the
// core's message.
#include "core/machines/profile_cutter/profile_cutter_spec.h"
#include "sim_rig.h"

#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/machines/profile_cutter/gcode_export.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/pipe_joint/template_pdf.h"
#include "core/pipe_joint/template_tiles.h"
#include "main_window_run.h"
#include "plots/tracking_plots_widget.h"
#include "ui/engine_bridge.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/machine_exports.h"
#include "ui/main_window.h"
#include "ui/panels/control_panel.h"
#include "ui/panels/monitor_views.h"
#include "ui/panels/progress_panel.h"
#include "ui/run_controller.h"

#include <QDoubleSpinBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>

#include <QRegularExpression>
#include <QtTest>

using cutcell::EngineState;
using CutCell::ui::MainWindow;

namespace {

const QString kJobFile = CUTCELL_SOURCE_DIR "/resources/jobs/profile_cutter_job.json";

// Waits until the GUI has a sample from at least `seconds` of engine time after its current
// one: "nothing changed" is then checked over that many cycles however slow the machine is
// (a fixed qWait checks fewer cycles, or none, when the machine is slow).
void waitForEngineTime(const MainWindow& w, double seconds) {
    const double from = w.run()->bridge()->last().time_s;
    QTRY_VERIFY_WITH_TIMEOUT(w.run()->bridge()->last().time_s >= from + seconds, 30000);
}

// Opens the job file and keeps run logs out of the source tree.
void openProfileJob(MainWindow& w) {
    QString err;
    QVERIFY2(w.openJob(kJobFile, &err), qPrintable(err));
    auto job = w.editor()->job();
    QCOMPARE(QString::fromStdString(job.machine), QString("profile_cutter_2axis"));
    job.engine.runs_dir = "";
    w.editor()->setJob(job);
}

} // namespace

class TestGuiProfile : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void runsToCompletedOnTwoAxes() {
        MainWindow w(&cutcell::app::makeRig);
        w.run()->setClockMode(cutcell::ClockMode::AsFastAsPossible);
        openProfileJob(w);
        w.show();
        QString why;
        QVERIFY2(autoRunCompletes(w, 240000, &why), qPrintable(why));
        w.run()->bridge()->poll();
        QCOMPARE(w.progress()->bar()->value(), w.progress()->bar()->maximum());
        const auto& last = w.run()->bridge()->last();
        QVERIFY(last.point_count > 0);
        QVERIFY(!last.torch_on);
        // The cut's X range was travelled (axis 1 is the carriage, in mm).
        const auto cut = cutcell::computeProfileCut(w.editor()->job());
        double xMin = 1e300, xMax = -1e300;
        for (const auto& p : cut.points) {
            xMin = std::min(xMin, p.x_mm);
            xMax = std::max(xMax, p.x_mm);
        }
        QVERIFY(last.actual[1] >= xMin - 1 && last.actual[1] <= xMax + 1);
        // Two joint traces, named for the machine; both plots got data.
        auto* plots = w.plots()->plots();
        QCOMPARE(plots->axisCount(), 2);
        QVERIFY(plots->axisNames().at(0).contains("A"));
        QCOMPARE(plots->axisUnits(), QStringList({"deg", "mm"}));
        QVERIFY(w.plots()->samplesAppended() > 0);
        QVERIFY(plots->sampleCount() > 0);
        plots->replotNow();
        QVERIFY(plots->plottedPointCount() > 0);
        QTemporaryDir dir;
        QString err;
        QVERIFY2(plots->exportCsv(dir.filePath("errors.csv"), &err), qPrintable(err));
        QFile csv(dir.filePath("errors.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QByteArray text = csv.readAll();
        QVERIFY(text.count('\n') > 10);
        // Each column in its unit; the tip column is the torch's miss on the pipe and carries
        // numbers (an empty cell is a NaN).
        const QList<QByteArray> rows = text.split('\n');
        QVERIFY(rows.size() > 3);
        QVERIFY2(rows.at(0).contains("_err_deg") && rows.at(0).contains("_err_mm"),
                 rows.at(0).constData());
        const QList<QByteArray> mid = rows.at(rows.size() / 2).split(',');
        QCOMPARE(mid.size(), 4); // t, A, X, miss
        QVERIFY(!mid.at(3).trimmed().isEmpty());
    }

    void emergencyStopLatchesInTheCut() {
        MainWindow w(&cutcell::app::makeRig);
        openProfileJob(w); // real time: the operator's pace
        w.show();
        QSignalSpy done(w.run(), &CutCell::ui::RunController::autoRunFinished);
        w.run()->startAutoRun();
        QTRY_VERIFY_WITH_TIMEOUT(
            w.run()->bridge()->last().torch_on && w.run()->bridge()->last().progress > 0, 30000);
        // Feed hold: the progress stops, Resume continues.
        QTest::mouseClick(w.controls()->holdButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::Paused, 5000);
        // The state comes from the newest sample: it is already Paused (on the path, at rest).
        QCOMPARE(w.run()->bridge()->last().state, EngineState::Paused);
        const double held = w.run()->bridge()->last().progress;
        waitForEngineTime(w, 0.3);
        if (QTest::currentTestFailed()) return;
        QCOMPARE(w.run()->bridge()->last().progress, held);
        QTest::mouseClick(w.controls()->eStopButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), EngineState::EmergencyStop, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!w.run()->bridge()->last().torch_on, 2000);
        waitForEngineTime(w, 0.3); // latched over 300 cycles, however slow the machine
        if (QTest::currentTestFailed()) return;
        QCOMPARE(state(w), EngineState::EmergencyStop);
        QVERIFY(!w.controls()->startButton()->isEnabled());
    }

    void formsShowTheProfilePage() {
        MainWindow w(&cutcell::app::makeRig);
        auto* params = w.parameters();
        QVERIFY(params->tabShown("Robot"));
        QVERIFY(!params->tabShown("Profile cutter"));
        openProfileJob(w);
        QVERIFY(params->tabShown("Profile cutter"));
        QVERIFY(!params->tabShown("Robot"));
        QVERIFY(!params->tabShown("Method"));
        QVERIFY(!params->fieldFor("cut.bevel_deg")->isEnabled());
        const auto job = w.editor()->job();
        for (const char* key :
             {"profile_cutter.steps_per_rev_a", "profile_cutter.pulses_per_step_a",
              "profile_cutter.mm_per_pulse_x", "profile_cutter.max_pulse_rate_hz",
              "profile_cutter.pierce_s", "profile_cutter.x_travel_mm"})
            QVERIFY2(params->fieldFor(key), key);
        // The fields show the job's values.
        auto* steps = qobject_cast<QSpinBox*>(params->fieldFor("profile_cutter.steps_per_rev_a"));
        QVERIFY(steps);
        QCOMPARE(steps->value(), cutcell::profileCutterSpec(job).steps_per_rev_a);
        // Live validation: an out-of-range entry is marked and named in the issues.
        auto* pierce = qobject_cast<QDoubleSpinBox*>(params->fieldFor("profile_cutter.pierce_s"));
        QVERIFY(pierce);
        pierce->setValue(-1);
        QTRY_VERIFY(!w.editor()->issues().empty());
        bool named = false;
        for (const auto& issue : w.editor()->issues())
            named = named || issue.key == "profile_cutter.pierce_s";
        QVERIFY(named);
        QVERIFY(!w.controls()->startButton()->isEnabled());
        // Back to a robot job: the robot's pages return.
        QVERIFY(w.newJob("pipe_robot_6axis"));
        QVERIFY(params->tabShown("Robot"));
        QVERIFY(!params->tabShown("Profile cutter"));
        QVERIFY(params->fieldFor("cut.bevel_deg")->isEnabled());
    }

    void exportsWriteFilesAndNameTheFileOnError() {
        using CutCell::ui::ExportKind;
        const auto job = cutcell::loadJobFile(kJobFile.toStdString());
        QTemporaryDir dir;
        QString err, summary;
        const QString ngc = dir.filePath("cut.ngc");
        QVERIFY2(CutCell::ui::exportCut(ExportKind::Gcode, job, ngc, &err, &summary),
                 qPrintable(err));
        QVERIFY(summary.contains(ngc));
        QFile f(ngc);
        QVERIFY(f.open(QIODevice::ReadOnly));
        // Same text as the core writer (what the CLI writes).
        QCOMPARE(f.readAll().toStdString(),
                 cutcell::profileGcode(job, cutcell::computeProfileCut(job)));
        const QString svg = dir.filePath("t.svg"), pdf = dir.filePath("t.pdf");
        QVERIFY2(CutCell::ui::exportCut(ExportKind::TemplateSvg, job, svg, &err), qPrintable(err));
        QVERIFY2(CutCell::ui::exportCut(ExportKind::TemplatePdf, job, pdf, &err), qPrintable(err));
        QFile s(svg), p(pdf);
        QVERIFY(s.open(QIODevice::ReadOnly) && s.readAll().contains("<svg"));
        QVERIFY(p.open(QIODevice::ReadOnly) && p.read(5) == "%PDF-");
        // On A4 the PDF is the core's tiles, one page each, as `cutcell-cli export --paper A4`.
        const QString a4 = dir.filePath("t_a4.pdf");
        QVERIFY2(CutCell::ui::exportCut(ExportKind::TemplatePdf, job, a4, &err, &summary, "A4"),
                 qPrintable(err));
        const auto drawing = cutcell::buildTemplate(job, cutcell::jointExtrasOf(job));
        const auto a4Paper = *cutcell::paperByName("A4");
        QFile t(a4);
        QVERIFY(t.open(QIODevice::ReadOnly));
        QCOMPARE(t.readAll().toStdString(),
                 cutcell::templatePdf(cutcell::templatePages(drawing, a4Paper, job.name)));
        QVERIFY2(summary.contains("sheets of A4"), qPrintable(summary));
        QVERIFY(!CutCell::ui::exportCut(ExportKind::TemplatePdf, job, a4, &err, nullptr, "A5"));
        QVERIFY2(err.contains("A5"), qPrintable(err));
        // A robot job has no G-code; a directory that does not exist cannot be written.
        const QString robotNgc = dir.filePath("robot.ngc");
        QVERIFY(!CutCell::ui::exportCut(ExportKind::Gcode, cutcell::defaultJob(), robotNgc, &err));
        QVERIFY2(err.contains(robotNgc) && err.contains("G-code"), qPrintable(err));
        QVERIFY(!QFile::exists(robotNgc));
        const QString bad = dir.filePath("missing/dir/t.svg");
        QVERIFY(!CutCell::ui::exportCut(ExportKind::TemplateSvg, job, bad, &err));
        QVERIFY(err.contains(bad));
    }

    void cutOffTheCarriageBlocksStart() {
        MainWindow w(&cutcell::app::makeRig);
        openProfileJob(w);
        auto job = w.editor()->job();
        cutcell::profileCutterSpec(job).x_travel_mm = 10; // far shorter than the cut's X range
        w.editor()->setJob(job);
        QTRY_VERIFY_WITH_TIMEOUT(!w.run()->planning(), 10000);
        // The refusal names the carriage's travel by its field's label, not the file's key.
        const QWidget* travel = w.parameters()->fieldFor("profile_cutter.x_travel_mm");
        QVERIFY(travel && !travel->accessibleName().isEmpty());
        QTRY_VERIFY2(w.run()->startBlockedReason().contains(travel->accessibleName()),
                     qPrintable(w.run()->startBlockedReason()));
        QVERIFY(!w.run()->startBlockedReason().contains("x_travel_mm"));
        QVERIFY(!w.controls()->startButton()->isEnabled());
    }

    // One validation for GUI and CLI: a pulse rate the card cannot give is refused by both, with
    // the same sentence (the GUI once accepted what `cutcell-cli validate` refused).
    void pulseRateOverTheCardBlocksStartAsInTheCli() {
        MainWindow w(&cutcell::app::makeRig);
        openProfileJob(w);
        auto job = w.editor()->job();
        cutcell::profileCutterSpec(job).max_pulse_rate_hz =
            50; // in range, far below what the cut needs
        w.editor()->setJob(job);
        const cutcell::MachinePlan cli = cutcell::machineFor(job).plan(job);
        QVERIFY(!cli.ok());
        QVERIFY(QString::fromStdString(cli.outcome.message).contains("max_pulse_rate_hz"));
        QTRY_VERIFY_WITH_TIMEOUT(!w.run()->planning(), 10000);
        // The same sentence, the key named by its field's label.
        const QString problem = QString::fromStdString(cli.outcome.message);
        const QString before = problem.left(problem.indexOf(
            QRegularExpression(R"((machine\.)?profile_cutter\.max_pulse_rate_hz)")));
        const QWidget* rate = w.parameters()->fieldFor("profile_cutter.max_pulse_rate_hz");
        QVERIFY(rate && !rate->accessibleName().isEmpty());
        QTRY_VERIFY2(
            w.run()->startBlockedReason().contains(before + rate->accessibleName() + " = 50 Hz"),
            qPrintable(w.run()->startBlockedReason() + " / " + problem));
        QVERIFY(!w.controls()->startButton()->isEnabled());
    }
};

QTEST_MAIN(TestGuiProfile)
#include "test_gui_profile.moc"
