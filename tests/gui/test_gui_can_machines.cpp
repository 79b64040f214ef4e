// Every machine with CANopen drives runs over CAN from the operator station (issue 20): its
// shipped job, switched to devices.kind = "canopen" on a private virtualcan bus hosted by this
// test, with the drive simulator in-process playing the machine's own cell
// (devices/machines/can_cells.cpp, the table the CLI uses too). Per machine: the device panel
// lists one node per axis and sensor, named as the machine names them; Enable, Home, Start run
// to Completed; E-STOP, Release and Reset; a pulled cable faults the engine naming a node, and
// Reset reconnects so Enable works again. The profile cutter (steppers on a pulse card) is
// refused with its module's reason.
#include "can_cable.h"
#include "sim_rig.h"

#include "core/engine/cycle_stats_text.h"
#include "core/job/job_io.h"
#include "core/machine/machine_module.h"
#include "core/machine/machine_registry.h"
#include "core/machines/flying_saw/flying_saw_module.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"
#include "core/machines/quick_return/quick_return_spec.h"
#include "core/machines/section_steel/section_catalogue.h"
#include "core/machines/section_steel/section_steel_module.h"
#include "core/machines/section_steel/section_steel_spec.h"
#include "devices/canopen/drive_simulator.h"
#include "devices/canopen/thread_priority.h"
#include "devices/canopen/virtualcan_host.h"
#include "devices/machines/can_cells.h"
#include "main_window_run.h"
#include "ui/device_panel.h"
#include "ui/link_control.h"
#include "ui/machine/machine_ui_registry.h"
#include "ui/main_window.h"
#include "ui/panels/alarm_panel.h"
#include "ui/panels/control_panel.h"
#include "ui/panels/event_log_panel.h"
#include "ui/run_controller.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QRegularExpression>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/support/free_local_port.h"
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <unistd.h>

using cutcell::EngineState;
using CutCell::ui::MainWindow;
using CutCell::ui::RigLink;

namespace {

// One column of the device tab's node table, by its header.
QStringList deviceColumn(const MainWindow& w, const QString& header) {
    QStringList out;
    auto* table = w.devicePanel()->findChild<QTableWidget*>();
    if (!table) return out;
    for (int c = 0; c < table->columnCount(); ++c)
        if (table->horizontalHeaderItem(c)->text() == header)
            for (int r = 0; r < table->rowCount(); ++r)
                out << (table->item(r, c) ? table->item(r, c)->text() : QString());
    return out;
}

// The engine's state and the last alarm, for a failure's message.
QByteArray why(const MainWindow& w) {
    QString text = QString::fromLatin1(cutcell::toString(state(w)));
    if (!w.alarms()->alarms().empty()) text += ": " + w.alarms()->alarms().back().text;
    return text.toUtf8();
}

// The run's tracking figures per axis in its unit and the bus's SYNC jitter, in the test's
// output: what a failed run was near, what a passed one had in hand.
void printTracking(MainWindow& w) {
    cutcell::TrackingReport report;
    if (!w.run()->rig() || !w.run()->rig()->engine().lastRunReport(report)) return;
    for (int i = 0; i < report.axis_count; ++i)
        std::fprintf(stderr, "axis %d: max |e| %.4f, rms %.4f %s over CAN\n", i, report.maxAbs(i),
                     report.rms(i), report.unit(i));
    std::fprintf(stderr, "engine: %s\n",
                 cutcell::cycleTimingLine(w.run()->rig()->engine().cycleStats()).c_str());
}

bool eventLogNamesANode(const MainWindow& w) {
    static const QRegularExpression node(QStringLiteral("\\bnode \\d+:"));
    for (int r = 0; r < w.eventLog()->rowCount(); ++r)
        if (node.match(w.eventLog()->message(r)).hasMatch()) return true;
    return false;
}

void click(QPushButton* b) {
    QVERIFY2(b->isEnabled(), qPrintable(b->text()));
    QTest::mouseClick(b, Qt::LeftButton);
}

// The shipped job of a machine, shortened where a whole run would take minutes.
cutcell::Job shippedJob(const std::string& id) {
    const cutcell::MachineModule* m = cutcell::findMachine(id);
    cutcell::Job job = m ? m->defaultJob() : cutcell::Job{};
    if (auto* saw = job.machine_spec.as<cutcell::FlyingSawSpec>()) saw->queue = {{6000, 2}};
    if (auto* steel = job.machine_spec.as<cutcell::section_steel::SectionSteelSpec>()) {
        // The square end of an L 50x50x5 angle: about 150 mm of outline.
        if (const auto angle = cutcell::section_steel::findSection("L 50x50x5")) {
            steel->section = *angle;
            steel->user_defined = false;
        }
    }
    if (id == cutcell::kPipeRobotId) job.cut.speed_mm_s = 15; // a shorter cut
    job.engine.runs_dir = "";
    return job;
}

} // namespace

class TestGuiCanMachines : public QObject {
    Q_OBJECT
    std::unique_ptr<QCanBusDevice> host_;
    quint16 busPort_ = 0;
    QTemporaryDir dir_;
    bool fifo_ = false;

    QString busUrl() const { return QStringLiteral("tcp://127.0.0.1:%1/can0").arg(busPort_); }

  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(dir_.isValid());
        busPort_ = static_cast<quint16>(cutcell::test::freeLocalPort());
        cutcell::canopen::hostVirtualCanBus("virtualcan", busUrl()); // not on this thread
        host_.reset(QCanBus::instance()->createDevice("virtualcan", busUrl()));
        QVERIFY(host_ && host_->connectDevice());
        QTRY_COMPARE(host_->state(), QCanBusDevice::ConnectedState);
        std::thread([this] { fifo_ = cutcell::canopen::raiseCallingThreadToFifo(1); }).join();
    }

    void everyMachineRunsOverCan_data() {
        QTest::addColumn<QString>("id");
        QTest::addColumn<double>("period"); // s: what the bus carries for the machine's nodes
        QTest::newRow("pipe robot") << QString(cutcell::kPipeRobotId) << 0.004;
        // 8 drives: 8 RPDOs + 8 TPDOs + SYNC, about 51 % of 1 Mbit/s at 4 ms (the job's drive
        // filters need a period of at most twice their 2 ms).
        QTest::newRow("section steel") << QString(cutcell::kSectionSteelId) << 0.004;
        // The saw at 4 ms here (2 ms in tests/devices, without a GUI): in this process at 2 ms
        // the engine missed 78-311 deadlines a run, its cycle held up to 21 ms, and the
        // carriage faulted in 5 runs of 6 (feedback 8-14 cycles late); at 4 ms 5 of 5 completed
        // with both cores busy (carriage max |e| 1.13 mm, turntable 0.46 deg, feeds 3.4 mm).
        QTest::newRow("flying saw") << QString(cutcell::kFlyingSawId) << 0.004;
        // The quick-return crank in CST at 1 ms (its shipped job: the cutting experiment, 3
        // strokes against the contact force). It faulted in 6 of 15 runs (10.6-15.5 deg of its
        // 10 deg limit) while the test's cable held every frame for 40 ms every 100 ms (no
        // TCP_NODELAY towards the bus: can_cable.h). Since: 12 of 12 runs, 8 of 8 with both
        // cores busy (max |e| 4.94-5.06 deg, rms 1.57-1.68 deg; the law without its delay
        // prediction 8 of 8 too, rms 2.5-2.6 deg).
        QTest::newRow("quick-return crank") << QString(cutcell::kQuickReturnId) << 0.001;
    }
    void everyMachineRunsOverCan() {
        QFETCH(QString, id);
        QFETCH(double, period);
        // Without SCHED_FIFO a loaded host holds the bus's threads past the heartbeat time
        // (tests/devices/canopen_machines_test.cpp measured it): say so, do not pass.
        if (!fifo_ && id != cutcell::kPipeRobotId) {
            // Exit 77: CTest reports the test skipped (a QSKIP would count as passed).
            std::fprintf(stderr,
                         "SKIP: %s needs SCHED_FIFO for the bus's threads "
                         "(CAP_SYS_NICE or an rtprio limit)\n",
                         qPrintable(id));
            std::exit(77);
        }
        CanCable cable(busPort_);
        cutcell::Job job = shippedJob(id.toStdString());
        job.sim.period_s = period;
        job.devices.kind = cutcell::DeviceKind::CanOpen;
        job.devices.can_plugin = "virtualcan";
        job.devices.can_interface =
            QStringLiteral("tcp://127.0.0.1:%1/can0").arg(cable.port()).toStdString();
        // The drive simulator plays the machine's cell, as `cutcell-cli drivesim` does.
        const cutcell::MachineModule& module = cutcell::machineFor(job);
        const cutcell::MachinePlan plan = module.plan(job);
        QVERIFY2(plan.ok(), plan.outcome.message.c_str());
        cutcell::CanCellConfig cell;
        std::string error;
        QVERIFY2(cutcell::makeCanCell(job, period, plan.program.get(), &cell, &error),
                 error.c_str());
        cutcell::canopen::DriveSimulatorConfig sc;
        sc.interface = busUrl();
        sc.nodes = cell.sim_drives;
        sc.encoders = cell.sim_encoders;
        cutcell::canopen::DriveSimulator sim(sc);
        QVERIFY2(sim.start(), qPrintable(sim.errorText()));

        MainWindow w(&cutcell::app::makeRig);
        w.resize(1280, 720);
        w.show();
        const QString path = dir_.filePath(id + ".json");
        cutcell::saveJobFile(job, path.toStdString());
        QString openError;
        QVERIFY2(w.openJob(path, &openError), qPrintable(openError));
        QTRY_VERIFY2_WITH_TIMEOUT(w.run()->rig() != nullptr,
                                  qPrintable(w.run()->startBlockedReason()), 30000);
        QVERIFY2(QString::fromStdString(w.run()->rig()->description())
                     .contains(QString::fromStdString(cell.description)),
                 w.run()->rig()->description().c_str());

        // The device tab: one row per node, each named by the machine's axis or sensor.
        QStringList expected;
        for (const cutcell::AxisInfo& a : module.axes(job))
            expected << QString::fromStdString(a.name);
        for (const std::string& s : module.sensorNames())
            expected << QString::fromStdString(s);
        QTRY_COMPARE_WITH_TIMEOUT(deviceColumn(w, "Axis").size(), expected.size(), 5000);
        const QStringList shown = deviceColumn(w, "Axis");
        for (int i = 0; i < cell.axis_count; ++i)
            QVERIFY2(shown[i].contains(expected[i].section(' ', 0, 0)),
                     qPrintable(shown.join(", ") + " / " + expected.join(", ")));
        for (int k = cell.axis_count; k < expected.size(); ++k)
            QCOMPARE(shown[k], expected[k]);

        // Enable, Home, Start by the buttons; the run completes.
        startManually(w);
        QTRY_VERIFY_WITH_TIMEOUT(state(w) != EngineState::Running, 120000);
        printTracking(w);
        QVERIFY2(state(w) == EngineState::Completed, why(w).constData());

        // E-STOP, Release, Reset.
        click(w.controls()->eStopButton());
        QTRY_VERIFY2_WITH_TIMEOUT(state(w) == EngineState::EmergencyStop, why(w).constData(), 2000);
        click(w.controls()->releaseButton());
        QTRY_VERIFY_WITH_TIMEOUT(w.controls()->resetButton()->isEnabled(), 2000);
        click(w.controls()->resetButton());
        QTRY_VERIFY_WITH_TIMEOUT(state(w) == EngineState::Idle, 5000);

        // The bus lost while enabled: Fault naming a node; Reset reconnects, Enable works.
        click(w.controls()->enableButton());
        QTRY_VERIFY2_WITH_TIMEOUT(state(w) == EngineState::Ready, why(w).constData(), 10000);
        cable.cut();
        QTRY_VERIFY2_WITH_TIMEOUT(state(w) == EngineState::Fault, why(w).constData(), 3000);
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->link()->link().state == RigLink::State::Lost, 3000);
        // The master names every node that lost the bus; the operator reads it in the log.
        QTRY_VERIFY2_WITH_TIMEOUT(eventLogNamesANode(w), qPrintable(lastLog(w)), 3000);
        cable.plugIn();
        click(w.controls()->resetButton()); // clears the fault and reconnects
        QTRY_VERIFY2_WITH_TIMEOUT(state(w) == EngineState::Idle, why(w).constData(), 2000);
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->link()->link().state == RigLink::State::Up, 10000);
        click(w.controls()->enableButton());
        QTRY_VERIFY2_WITH_TIMEOUT(state(w) == EngineState::Ready, why(w).constData(), 10000);
        click(w.controls()->eStopButton());
    }

    void profileCutterIsRefusedWithItsReason() {
        cutcell::Job job = shippedJob(cutcell::kProfileCutterId);
        job.devices.kind = cutcell::DeviceKind::CanOpen;
        job.devices.can_interface = busUrl().toStdString();
        const cutcell::Outcome can = cutcell::machineFor(job).canOpen();
        QVERIFY(can.refused());
        QCOMPARE(can.key, std::string("devices.kind"));
        const std::string& why = can.message;
        MainWindow w(&cutcell::app::makeRig);
        const QString path = dir_.filePath("profile.json");
        cutcell::saveJobFile(job, path.toStdString());
        QString openError;
        if (w.openJob(path, &openError)) {
            // Opened: the rig is refused with the module's reason, Start stays blocked.
            QTRY_VERIFY2_WITH_TIMEOUT(
                w.run()->startBlockedReason().contains(QString::fromStdString(why).left(30)),
                qPrintable(w.run()->startBlockedReason()), 30000);
            QVERIFY(w.run()->rig() == nullptr);
        } else {
            QVERIFY2(openError.contains("pulse card"), qPrintable(openError));
        }
    }
};

QTEST_MAIN(TestGuiCanMachines)
#include "test_gui_can_machines.moc"
