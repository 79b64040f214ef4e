// The CAN bus from the operator column, against the in-process drive simulator on a private
// virtualcan bus hosted by this test. The master reaches the bus through a cable (a TCP relay,
// can_cable.h) that the test can pull. Properties:
//  - opening a CANopen job touches no bus; the bus box says "down" and the status bar names
//    the CANopen cell;
//  - Enable with no drive answering shows progress, then fails naming the plugin, the
//    interface and every node, releases the connection and leaves the engine Idle; Enable
//    again (simulator running) brings every node to Operation enabled; the GUI thread keeps
//    running its events throughout;
//  - a bus lost while Idle shows in the bus box (lost, rows greyed) and Reconnect brings it
//    back; a bus lost while enabled faults the engine, and Reset reconnects so Enable works;
//  - E-STOP during the bring-up stops the machine, and the bus coming up enables nothing.
#include "can_cable.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "devices/machines/can_cells.h"
#include "sim_rig.h"

#include "main_window_run.h"

#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "devices/canopen/drive_simulator.h"
#include "devices/canopen/virtualcan_host.h"
#include "ui/engine_bridge.h"
#include "ui/language.h"
#include "ui/link_control.h"
#include "ui/main_window.h"
#include "ui/panels/bus_panel.h"
#include "ui/panels/control_panel.h"
#include "ui/panels/event_log_panel.h"
#include "ui/run_controller.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QElapsedTimer>
#include <QLabel>
#include <QPushButton>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include "tests/support/free_local_port.h"
#include <memory>
#include <unistd.h>

using cutcell::EngineState;
using CutCell::ui::MainWindow;
using CutCell::ui::RigLink;

namespace {

RigLink::State linkState(const MainWindow& w) {
    return w.run()->link()->link().state;
}

// One column of the bus box's node table.
QStringList column(const MainWindow& w, int c) {
    QStringList out;
    const QTableWidget* t = w.busPanel()->nodeTable();
    for (int r = 0; r < t->rowCount(); ++r)
        out << (t->item(r, c) ? t->item(r, c)->text() : QString());
    return out;
}
QStringList cia402(const MainWindow& w) {
    return column(w, 2);
}

bool all(const QStringList& l, const QString& s) {
    return l.size() == cutcell::kAxisCount && l.count(s) == l.size();
}

int staleRows(const MainWindow& w) {
    int n = 0;
    for (int r = 0; r < w.busPanel()->nodeTable()->rowCount(); ++r)
        n += w.busPanel()->rowStale(r) ? 1 : 0;
    return n;
}

QString statusBarText(const MainWindow& w) {
    QStringList texts;
    for (const QLabel* l : w.statusBar()->findChildren<QLabel*>())
        texts << l->text();
    return texts.join(QStringLiteral(" | "));
}

// The longest time the GUI thread went without running a 5 ms timer.
class StallProbe : public QObject {
  public:
    StallProbe() {
        timer_.setInterval(5);
        connect(&timer_, &QTimer::timeout, this,
                [this] { maxMs_ = std::max(maxMs_, since_.restart()); });
        since_.start();
        timer_.start();
    }
    qint64 maxMs() const { return maxMs_; }

  private:
    QTimer timer_;
    QElapsedTimer since_;
    qint64 maxMs_ = 0;
};

void click(QPushButton* b) {
    QVERIFY2(b->isEnabled(), qPrintable(b->text()));
    QTest::mouseClick(b, Qt::LeftButton);
}

} // namespace

class TestGuiCanLink : public QObject {
    Q_OBJECT
    std::unique_ptr<QCanBusDevice> host_;
    quint16 busPort_ = 0;
    QTemporaryDir dir_;

    QString busUrl() const { return QStringLiteral("tcp://127.0.0.1:%1/can0").arg(busPort_); }
    cutcell::Job canJob(const CanCable& cable) const {
        auto job = cutcell::defaultJob();
        job.devices.kind = cutcell::DeviceKind::CanOpen;
        job.devices.can_plugin = "virtualcan";
        job.devices.can_interface =
            QStringLiteral("tcp://127.0.0.1:%1/can0").arg(cable.port()).toStdString();
        job.sim.period_s = 0.004;
        job.engine.runs_dir = "";
        return job;
    }
    std::unique_ptr<cutcell::canopen::DriveSimulator> startSimulator(const cutcell::Job& job) {
        cutcell::canopen::DriveSimulatorConfig sc;
        sc.interface = busUrl();
        sc.nodes =
            cutcell::canCellDriveNodes(job, {job.devices.node_ids.begin(),
                                             job.devices.node_ids.begin() + cutcell::kAxisCount});
        auto sim = std::make_unique<cutcell::canopen::DriveSimulator>(sc);
        if (!sim->start()) return nullptr;
        return sim;
    }
    // A window with the job open and its rig built (the bus down).
    void openWindow(MainWindow& w, const cutcell::Job& job, const QString& name) {
        w.resize(1600, 1000);
        w.show();
        const QString path = dir_.filePath(name);
        cutcell::saveJobFile(job, path.toStdString());
        QString error;
        QVERIFY2(w.openJob(path, &error), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->rig() != nullptr, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->bridge()->state() == EngineState::Idle, 5000);
    }
    static void screenshot(MainWindow& w, const char* name) {
        // For docs/: CUTCELL_TEST_SCREENSHOT_DIR=docs (under xvfb-run for the real look).
        const QString dir = qEnvironmentVariable("CUTCELL_TEST_SCREENSHOT_DIR");
        if (!dir.isEmpty()) QVERIFY(w.grab().save(dir + QLatin1Char('/') + name));
    }

  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(dir_.isValid());
        busPort_ = static_cast<quint16>(cutcell::test::freeLocalPort());
        cutcell::canopen::hostVirtualCanBus("virtualcan", busUrl()); // not on this thread
        host_.reset(QCanBus::instance()->createDevice("virtualcan", busUrl()));
        QVERIFY(host_ && host_->connectDevice());
        QTRY_COMPARE(host_->state(), QCanBusDevice::ConnectedState);
    }

    void enableBringsTheBusUpAndAFailureIsClearAndRetried() {
        CanCable cable(busPort_);
        const cutcell::Job job = canJob(cable);
        MainWindow w(&cutcell::app::makeRig);
        openWindow(w, job, "link.json");
        QVERIFY(w.busPanel()->isVisible());
        QCOMPARE(linkState(w), RigLink::State::Down);
        QVERIFY2(statusBarText(w).contains("CANopen cell"), qPrintable(statusBarText(w)));
        QVERIFY(!statusBarText(w).contains("imulated cell"));
        QTest::qWait(1000);
        QCOMPARE(cable.accepted(), 0); // nothing tried before Enable

        // No drive answers: progress, then a failure that names plugin, interface and nodes.
        StallProbe probe;
        click(w.controls()->enableButton());
        QTRY_COMPARE_WITH_TIMEOUT(linkState(w), RigLink::State::Connecting, 1000);
        QVERIFY(w.busPanel()->stateLabel()->text().contains("CONNECTING"));
        QTRY_COMPARE_WITH_TIMEOUT(linkState(w), RigLink::State::Failed, 10000);
        const QString why = w.busPanel()->detailLabel()->toolTip();
        QVERIFY2(why.contains("virtualcan") && why.contains(QString::number(cable.port())),
                 qPrintable(why));
        QString nodes;
        // The machine's axes' nodes (node_ids holds up to kMaxAxes slots).
        const size_t axisCount = cutcell::machineFor(job).axes(job).size();
        for (size_t i = 0; i < axisCount; ++i)
            nodes += (nodes.isEmpty() ? "" : ", ") + QString::number(job.devices.node_ids[i]);
        QVERIFY2(why.contains("nodes " + nodes + ":"), qPrintable(why));
        QVERIFY2(w.run()->startBlockedReason().contains("press Enable to try again"),
                 qPrintable(w.run()->startBlockedReason()));
        QTRY_COMPARE_WITH_TIMEOUT(cable.open(), 0, 2000); // the connection is released
        QCOMPARE(w.run()->bridge()->state(), EngineState::Idle);
        qInfo("GUI thread: longest stall during the failed bring-up %lld ms", probe.maxMs());
        QVERIFY2(probe.maxMs() < 150, qPrintable(QString::number(probe.maxMs())));

        // The drives are there now: Enable again connects, configures and enables them.
        auto sim = startSimulator(job);
        QVERIFY(sim);
        click(w.controls()->enableButton());
        QTRY_VERIFY2_WITH_TIMEOUT(all(cia402(w), "Operation enabled"),
                                  qPrintable(cia402(w).join(", ")), 10000);
        QTRY_COMPARE_WITH_TIMEOUT(w.run()->bridge()->state(), EngineState::Ready, 5000);
        QCOMPARE(linkState(w), RigLink::State::Up);
        QTRY_COMPARE_WITH_TIMEOUT(cable.open(), 1, 2000); // the master's one connection
        QTRY_COMPARE_WITH_TIMEOUT(staleRows(w), 0, 2000);
        QVERIFY(statusBarText(w).contains("bus up"));
        screenshot(w, "can_bus_up.png");
        click(w.controls()->eStopButton());
        QTRY_COMPARE_WITH_TIMEOUT(w.run()->bridge()->state(), EngineState::EmergencyStop, 2000);
    }

    void busLostWhileIdleShowsAndReconnects() {
        CanCable cable(busPort_);
        const cutcell::Job job = canJob(cable);
        auto sim = startSimulator(job);
        QVERIFY(sim);
        MainWindow w(&cutcell::app::makeRig);
        openWindow(w, job, "idle.json");
        QCOMPARE(w.busPanel()->reconnectButton()->text(), QStringLiteral("Connect"));
        click(w.busPanel()->reconnectButton());
        QTRY_COMPARE_WITH_TIMEOUT(linkState(w), RigLink::State::Up, 10000);
        QTRY_VERIFY2_WITH_TIMEOUT(all(column(w, 1), "Operational"),
                                  qPrintable(column(w, 1).join(", ")), 2000);
        QTRY_COMPARE_WITH_TIMEOUT(staleRows(w), 0, 2000);
        QVERIFY(!cia402(w).contains("Operation enabled")); // connected, nothing enabled
        QCOMPARE(w.run()->bridge()->state(), EngineState::Idle);

        cable.cut();
        QTRY_COMPARE_WITH_TIMEOUT(linkState(w), RigLink::State::Lost, 3000);
        QVERIFY(w.busPanel()->stateLabel()->text().contains("LOST"));
        QVERIFY(w.run()->startBlockedReason().contains("CAN bus lost"));
        // Every row greyed once its heartbeat is older than the timeout.
        QTRY_COMPARE_WITH_TIMEOUT(staleRows(w), cutcell::kAxisCount,
                                  static_cast<int>(job.devices.heartbeat_timeout_ms) + 1000);
        QCOMPARE(w.run()->bridge()->state(), EngineState::Idle);
        screenshot(w, "can_bus_lost.png");

        cable.plugIn();
        click(w.busPanel()->reconnectButton());
        QTRY_COMPARE_WITH_TIMEOUT(linkState(w), RigLink::State::Up, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(staleRows(w), 0, 2000);
        click(w.controls()->enableButton());
        QTRY_COMPARE_WITH_TIMEOUT(w.run()->bridge()->state(), EngineState::Ready, 5000);
        QTRY_VERIFY2_WITH_TIMEOUT(all(cia402(w), "Operation enabled"),
                                  qPrintable(cia402(w).join(", ")), 5000);
        click(w.controls()->eStopButton());
    }

    void busLostWhileEnabledFaultsAndResetReconnects() {
        CanCable cable(busPort_);
        const cutcell::Job job = canJob(cable);
        auto sim = startSimulator(job);
        QVERIFY(sim);
        MainWindow w(&cutcell::app::makeRig);
        openWindow(w, job, "enabled.json");
        click(w.controls()->enableButton());
        QTRY_COMPARE_WITH_TIMEOUT(w.run()->bridge()->state(), EngineState::Ready, 10000);

        cable.cut();
        QTRY_COMPARE_WITH_TIMEOUT(w.run()->bridge()->state(), EngineState::Fault, 3000);
        QVERIFY(!w.run()->bridge()->last().torch_on);
        QTRY_COMPARE_WITH_TIMEOUT(linkState(w), RigLink::State::Lost, 3000);
        QVERIFY2(w.run()->startBlockedReason().contains("press Reset"),
                 qPrintable(w.run()->startBlockedReason()));

        cable.plugIn();
        click(w.controls()->resetButton()); // clears the fault and reconnects
        QTRY_COMPARE_WITH_TIMEOUT(w.run()->bridge()->state(), EngineState::Idle, 2000);
        QTRY_COMPARE_WITH_TIMEOUT(linkState(w), RigLink::State::Up, 10000);
        click(w.controls()->enableButton()); // once failed here with 0x8100 (bus lost)
        QTRY_VERIFY2_WITH_TIMEOUT(w.run()->bridge()->state() == EngineState::Ready,
                                  qPrintable(lastLog(w)), 5000);
        QTRY_VERIFY2_WITH_TIMEOUT(all(cia402(w), "Operation enabled"),
                                  qPrintable(cia402(w).join(", ")), 5000);
        click(w.controls()->eStopButton());
    }

    void emergencyStopDuringBringUpEnablesNothing() {
        CanCable cable(busPort_);
        const cutcell::Job job = canJob(cable);
        auto sim = startSimulator(job);
        QVERIFY(sim);
        MainWindow w(&cutcell::app::makeRig);
        openWindow(w, job, "estop.json");
        click(w.controls()->enableButton());
        QTRY_COMPARE_WITH_TIMEOUT(linkState(w), RigLink::State::Connecting, 1000);
        QElapsedTimer pressed;
        pressed.start();
        click(w.controls()->eStopButton());
        QTRY_COMPARE_WITH_TIMEOUT(w.run()->bridge()->state(), EngineState::EmergencyStop, 1000);
        qInfo("E-STOP during the bring-up: engine in EmergencyStop %lld ms after the click",
              pressed.elapsed());
        QTRY_COMPARE_WITH_TIMEOUT(linkState(w), RigLink::State::Up, 10000);
        QTest::qWait(500);
        QVERIFY2(!cia402(w).contains("Operation enabled"), qPrintable(cia402(w).join(", ")));
        QCOMPARE(w.run()->bridge()->state(), EngineState::EmergencyStop);
        click(w.controls()->releaseButton());
        click(w.controls()->resetButton());
        QTRY_COMPARE_WITH_TIMEOUT(w.run()->bridge()->state(), EngineState::Idle, 2000);
        QTest::qWait(500); // the cancelled Enable stays cancelled
        QCOMPARE(w.run()->bridge()->state(), EngineState::Idle);
        QVERIFY(!cia402(w).contains("Operation enabled"));
    }

    // The CAN master's and the link's texts in German (issue 21): the failed bring-up's reason
    // in the bus box and the Start reason, then the drives' CiA 402 states and the master's
    // events in the log once the bus is up; numbers and node lists as they came.
    void busTextsReadInGerman() {
        QVERIFY(CutCell::ui::applyGuiLanguage("de"));
        CanCable cable(busPort_);
        const cutcell::Job job = canJob(cable);
        {
            MainWindow w(&cutcell::app::makeRig);
            openWindow(w, job, "german.json");
            click(w.controls()->enableButton());
            QTRY_COMPARE_WITH_TIMEOUT(linkState(w), RigLink::State::Failed, 10000);
            const QString why = w.busPanel()->detailLabel()->toolTip();
            const QString english = QString::fromStdString(w.run()->link()->link().text);
            QVERIFY2(english.contains("nodes did not come up") && english.contains("no boot-up"),
                     qPrintable(english));
            QVERIFY2(why.contains("Knoten sind nicht hochgefahren") &&
                         why.contains("kein Boot-up innerhalb von 1000 ms"),
                     qPrintable(why));
            QVERIFY2(!why.contains("no boot-up") && !why.contains("did not come up"),
                     qPrintable(why));
            QVERIFY2(w.run()->startBlockedReason().contains("kein Boot-up"),
                     qPrintable(w.run()->startBlockedReason()));

            auto sim = startSimulator(job);
            QVERIFY(sim);
            click(w.controls()->enableButton());
            QTRY_VERIFY2_WITH_TIMEOUT(all(cia402(w), "Betrieb freigegeben"),
                                      qPrintable(cia402(w).join(", ")), 10000);
            QVERIFY2(all(column(w, 1), "Operational"), qPrintable(column(w, 1).join(", ")));
            QString log;
            for (int r = 0; r < w.eventLog()->rowCount(); ++r)
                log += w.eventLog()->message(r) + QLatin1Char('\n');
            QVERIFY2(log.contains("konfiguriert (CSP, RPDO1/RPDO2/TPDO1, Heartbeat"),
                     qPrintable(log.right(2000)));
            QVERIFY2(!log.contains("and operational"), qPrintable(log.right(2000)));
            click(w.controls()->eStopButton());
            QTRY_COMPARE_WITH_TIMEOUT(w.run()->bridge()->state(), EngineState::EmergencyStop, 2000);
        }
        QVERIFY(CutCell::ui::applyGuiLanguage("en"));
    }
};

QTEST_MAIN(TestGuiCanLink)
#include "test_gui_can_link.moc"
