// The main window driving CANopen drives: a canopen job opened as the operator would builds
// the CAN rig (master, six CiA 402 axes) on a private virtualcan bus hosted by this test, with
// the drive simulator in-process as a real bus peer. Enable brings every node to Operation
// enabled in the device panel; E-STOP takes every node out of it. A cycle too short for the
// bus is refused with the bus-load message as the rig error.
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "devices/machines/can_cells.h"
#include "sim_rig.h"

#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "devices/canopen/drive_simulator.h"
#include "devices/canopen/virtualcan_host.h"
#include "ui/device_panel.h"
#include "ui/engine_bridge.h"
#include "ui/main_window.h"
#include "ui/run_controller.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/support/free_local_port.h"
#include <memory>
#include <unistd.h>

using CutCell::ui::MainWindow;

namespace {

// CiA 402 column of the device panel's node table, one entry per node.
QStringList cia402States(const MainWindow& w) {
    QStringList states;
    auto* table = w.devicePanel()->findChild<QTableWidget*>();
    if (!table) return states;
    int column = -1;
    for (int c = 0; c < table->columnCount(); ++c)
        if (table->horizontalHeaderItem(c)->text() == "CiA 402") column = c;
    for (int r = 0; column >= 0 && r < table->rowCount(); ++r)
        states << (table->item(r, column) ? table->item(r, column)->text() : QString());
    return states;
}

bool allAre(const QStringList& states, const QString& s) {
    return states.size() == cutcell::kAxisCount && states.count(s) == states.size();
}

bool noneIs(const QStringList& states, const QString& s) {
    return states.size() == cutcell::kAxisCount && !states.contains(s);
}

} // namespace

class TestGuiCan : public QObject {
    Q_OBJECT
    std::unique_ptr<QCanBusDevice> host_;
    QString interface_;
    QTemporaryDir dir_;

    cutcell::Job canJob(double period_s) const {
        auto job = cutcell::defaultJob();
        job.devices.kind = cutcell::DeviceKind::CanOpen;
        job.devices.can_plugin = "virtualcan";
        job.devices.can_interface = interface_.toStdString();
        job.sim.period_s = period_s;
        job.cut.speed_mm_s = 15; // a short cut
        job.sim.duration_s = 1;
        job.engine.runs_dir = "";
        return job;
    }
    QString saveJob(const cutcell::Job& job, const QString& name) const {
        const QString path = dir_.filePath(name);
        cutcell::saveJobFile(job, path.toStdString());
        return path;
    }

  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(dir_.isValid());
        interface_ = QString("tcp://127.0.0.1:%1/can0").arg(cutcell::test::freeLocalPort());
        cutcell::canopen::hostVirtualCanBus("virtualcan", interface_); // not on this thread
        host_.reset(QCanBus::instance()->createDevice("virtualcan", interface_));
        QVERIFY(host_ && host_->connectDevice());
        QTRY_COMPARE(host_->state(), QCanBusDevice::ConnectedState);
    }

    void enableAndEmergencyStopShowInDevicePanel() {
        const cutcell::Job job = canJob(0.004); // the controller filters need tau_f >= period / 2
        cutcell::canopen::DriveSimulatorConfig sc;
        sc.interface = interface_;
        sc.nodes =
            cutcell::canCellDriveNodes(job, {job.devices.node_ids.begin(),
                                             job.devices.node_ids.begin() + cutcell::kAxisCount});
        cutcell::canopen::DriveSimulator sim(sc);
        QVERIFY2(sim.start(), qPrintable(sim.errorText()));

        MainWindow w(&cutcell::app::makeRig);
        w.resize(1440, 900);
        w.show();
        QString error;
        QVERIFY2(w.openJob(saveJob(job, "can.json"), &error), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->rig() != nullptr, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->bridge()->state() == cutcell::EngineState::Idle, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(cia402States(w).size() == cutcell::kAxisCount, 2000);

        w.run()->enable();
        QTRY_VERIFY2_WITH_TIMEOUT(allAre(cia402States(w), "Operation enabled"),
                                  qPrintable(cia402States(w).join(", ")), 5000);
        // For a look at the window: CUTCELL_TEST_SCREENSHOT=/tmp/can.png
        if (const QString shot = qEnvironmentVariable("CUTCELL_TEST_SCREENSHOT"); !shot.isEmpty())
            QVERIFY(w.grab().save(shot));
        w.run()->emergencyStop();
        QTRY_VERIFY2_WITH_TIMEOUT(noneIs(cia402States(w), "Operation enabled"),
                                  qPrintable(cia402States(w).join(", ")), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(w.run()->bridge()->state(), cutcell::EngineState::EmergencyStop,
                                  5000);
    }

    void tooShortCycleIsRefusedWithTheBusLoad() {
        MainWindow w(&cutcell::app::makeRig);
        QString error;
        QVERIFY2(w.openJob(saveJob(canJob(0.0005), "fast.json"), &error), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->startBlockedReason().contains("bus load"), 30000);
        QVERIFY(w.run()->rig() == nullptr);
    }
};

QTEST_MAIN(TestGuiCan)
#include "test_gui_can.moc"
