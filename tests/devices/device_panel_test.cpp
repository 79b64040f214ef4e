// The device panel fed from a live CAN master (simulated drives, one with an injected EMCY)
// through the app's glue; offscreen. Saves device_panel.png next to the test for a look.
#include "app/gui/can_panel_feed.h"
#include "core/job/default_job.h"
#include "devices/canopen/drive_simulator.h"
#include "devices/machines/can_cells.h"
#include "ui/device_panel.h"

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QtTest>

#include "tests/support/free_local_port.h"
#include <unistd.h>

using namespace cutcell;
using namespace cutcell::canopen;

class DevicePanelTest : public QObject {
    Q_OBJECT
  private slots:
    void showsNodesBusAndFaultsFromTheMaster() {
        // The panel first: the first widget of a process loads fonts and styles (about a second
        // under ASan on a loaded machine), which must not fall inside the bus's supervision.
        ui::DevicePanel panel;
        panel.resize(900, 420);
        panel.grab();
        Job job = defaultJob();
        // This test is about what the panel shows, not bus timing (tests/devices/canopen_*
        // check the supervision): a heartbeat timeout that a loaded, sanitised run cannot
        // trip by a stall (the last CI lost all heartbeats for 968 ms > 300 ms).
        job.devices.heartbeat_timeout_ms = 3000;
        job.devices.can_interface =
            QString("tcp://127.0.0.1:%1/can0").arg(cutcell::test::freeLocalPort()).toStdString();
        DriveSimulatorConfig sc;
        sc.interface = QString::fromStdString(job.devices.can_interface);
        sc.nodes = cutcell::canCellDriveNodes(job, {1, 2, 3});
        sc.nodes[1].faults.fault_code = 0x2310;
        sc.nodes[1].faults.fault_after_s = 0.1;
        DriveSimulator sim(sc);
        QVERIFY2(sim.start(), qPrintable(sim.errorText()));
        CanOpenMaster m(masterConfigFromJob(job, 0.004, 3));
        std::string error;
        QVERIFY2(m.start(&error), error.c_str());
        QTRY_VERIFY_WITH_TIMEOUT(m.allOperational(), 5000);
        for (int i = 0; i < 3; ++i)
            m.drive(i)->activate();
        QTRY_VERIFY_WITH_TIMEOUT(m.drive(1)->read(0).state == DriveState::Fault, 3000);

        panel.setChoice({true, "virtualcan", "can0", 1000000});
        panel.setSnapshot(app::toPanelSnapshot(m.snapshot(), {"0 chuck", "1 arm", "2 arm"}));
        auto* table = panel.findChild<QTableWidget*>();
        QVERIFY(table);
        QCOMPARE(table->rowCount(), 3);
        QCOMPARE(table->item(0, 0)->text(), QString("1"));
        QCOMPARE(table->item(0, 2)->text(), QString("Operational"));
        QCOMPARE(table->item(0, 3)->text(), QString("Operation enabled"));
        QCOMPARE(table->item(1, 3)->text(), QString("Fault"));
        QVERIFY(table->item(1, 5)->text().contains("over-current"));
        bool loadShown = false;
        for (QLabel* l : panel.findChildren<QLabel*>())
            loadShown = loadShown || l->text().startsWith("Load: ");
        QVERIFY(loadShown);
        panel.grab().save(QCoreApplication::applicationDirPath() + "/device_panel.png");

        QSignalSpy reset(&panel, &ui::DevicePanel::faultResetRequested);
        QSignalSpy edited(&panel, &ui::DevicePanel::choiceEdited);
        panel.findChild<QPushButton*>()->click();
        QCOMPARE(reset.count(), 1);
        panel.findChild<QComboBox*>()->setCurrentIndex(0);
        QCOMPARE(edited.count(), 1);
        QVERIFY(!panel.choice().can);
        m.stop();
    }
};

QTEST_MAIN(DevicePanelTest)
#include "device_panel_test.moc"
