// The CANopen master against the drive simulator on a virtualcan bus hosted by this process
// (the listener connects first, so the bus lives on the test's main thread; QTRY_* keeps its
// event loop running). The simulator runs on its own thread with its own bus client: a real
// peer, not a mock.
#include "core/job/default_job.h"
#include "devices/canopen/canopen_master.h"
#include "devices/canopen/drive_simulator.h"
#include "devices/canopen/emcy.h"
#include "devices/canopen/pdo.h"
#include "devices/canopen/qt_can_frame.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QProcess>
#include <QRegularExpression>
#include <QtTest>

#include <cmath>
#include <memory>

using namespace cutcell;
using namespace cutcell::canopen;

class CanOpenBusTest : public QObject {
    Q_OBJECT

    std::unique_ptr<QCanBusDevice> listener_;
    QList<QCanBusFrame> heard_;
    Job job_ = defaultJob();

    std::unique_ptr<DriveSimulator>
    simulator(const std::vector<int>& ids,
              const std::function<void(DriveNodeConfig&)>& tweak = {}) {
        DriveSimulatorConfig c;
        c.nodes = nodesFromJob(job_, ids);
        if (tweak)
            for (DriveNodeConfig& n : c.nodes)
                tweak(n);
        auto sim = std::make_unique<DriveSimulator>(c);
        if (!sim->start()) qFatal("simulator: %s", qPrintable(sim->errorText()));
        return sim;
    }
    std::unique_ptr<CanOpenMaster> master(int axes = 6, double period_s = 0.004) {
        auto m = std::make_unique<CanOpenMaster>(masterConfigFromJob(job_, period_s, axes));
        std::string error;
        if (!m->start(&error)) qFatal("master: %s", error.c_str());
        return m;
    }
    // The engine's side of a cycle for every axis: read, then hold the actual position.
    static void engineCycle(CanOpenMaster& m) {
        for (int i = 0; i < m.driveCount(); ++i) {
            const DriveFeedback fb = m.drive(i)->read(0);
            m.drive(i)->write(fb.position);
        }
    }
    static bool allInState(CanOpenMaster& m, DriveState s) {
        for (int i = 0; i < m.driveCount(); ++i) {
            const DriveFeedback fb = m.drive(i)->read(0);
            m.drive(i)->write(fb.position);
            if (fb.state != s) return false;
        }
        return true;
    }
    static void enableAll(CanOpenMaster& m) {
        QTRY_VERIFY_WITH_TIMEOUT(m.allOperational(), 5000);
        for (int i = 0; i < m.driveCount(); ++i)
            m.drive(i)->activate();
        QTRY_VERIFY_WITH_TIMEOUT(allInState(m, DriveState::Enabled), 3000);
    }

  private slots:
    void initTestCase() {
        QString err;
        listener_.reset(QCanBus::instance()->createDevice("virtualcan", "can0", &err));
        QVERIFY2(listener_, qPrintable(err));
        connect(listener_.get(), &QCanBusDevice::framesReceived, this, [this] {
            while (listener_->framesAvailable())
                heard_.append(listener_->readFrame());
        });
        QVERIFY(listener_->connectDevice());
        QTRY_COMPARE(listener_->state(), QCanBusDevice::ConnectedState);
    }

    void busLoadOverLimitIsRefusedWithFigures() {
        CanOpenMaster m(masterConfigFromJob(job_, 0.001, 6));
        std::string error;
        QVERIFY(!m.start(&error));
        QVERIFY2(error.find("13 frames") != std::string::npos, error.c_str());
        QVERIFY2(error.find("limit is 80 %") != std::string::npos, error.c_str());
        QVERIFY2(error.find("use a period >=") != std::string::npos, error.c_str());
    }

    void missingPluginIsReported() {
        CanOpenMasterConfig c = masterConfigFromJob(job_, 0.004, 1);
        c.plugin = "no-such-plugin";
        CanOpenMaster m(c);
        std::string error;
        QVERIFY(!m.start(&error, 1000));
        QVERIFY2(error.find("no-such-plugin") != std::string::npos, error.c_str());
    }

    void sixNodesStartToOperationEnabled() {
        auto sim = simulator({1, 2, 3, 4, 5, 6});
        auto m = master();
        enableAll(*m);
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                for (const SimNodeSnapshot& s : sim->snapshot())
                    if (s.state != Cia402State::OperationEnabled || s.nmt != NmtState::Operational)
                        return false;
                return true;
            }(),
            2000);
        const CanBusSnapshot snap = m->snapshot();
        QCOMPARE(snap.nodes.size(), size_t(6));
        for (const CanNodeSnapshot& n : snap.nodes) {
            QVERIFY(n.configured);
            QCOMPARE(n.state, Cia402State::OperationEnabled);
            QVERIFY(n.heartbeat_age_ms >= 0 && n.heartbeat_age_ms < 300);
        }
    }

    void emergencyStopTakesEveryNodeOutOfOperationEnabled() {
        auto sim = simulator({1, 2, 3, 4, 5, 6});
        auto m = master();
        enableAll(*m);
        const qsizetype before = heard_.size();
        for (int i = 0; i < m->driveCount(); ++i)
            m->drive(i)->quickStop(); // as the engine does
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                for (const SimNodeSnapshot& s : sim->snapshot())
                    if (s.state == Cia402State::OperationEnabled) return false;
                return true;
            }(),
            2000);
        // The stop went out on the asynchronous RPDO2 of every node (not waiting for SYNC).
        QSet<int> stopped;
        for (qsizetype k = before; k < heard_.size(); ++k) {
            CanFrame f;
            std::uint16_t c = 0;
            if (fromQt(heard_[k], f) && decodeRpdo2(f, c) && c == cw::kQuickStop)
                stopped.insert(cob::nodeOf(f.id));
        }
        QCOMPARE(stopped.size(), 6);
        // Category 0 from the master directly: disable voltage everywhere.
        m->emergencyStop(true);
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                for (const SimNodeSnapshot& s : sim->snapshot())
                    if (s.state != Cia402State::SwitchOnDisabled) return false;
                return true;
            }(),
            2000);
    }

    void heartbeatLossEndsInFaultWithNodeAndReason() {
        auto sim = simulator({1, 2, 3}, [](DriveNodeConfig& n) {
            if (n.node == 3) n.faults.heartbeat_stop_after_s = 0.3;
        });
        auto m = master(3);
        enableAll(*m);
        QTRY_VERIFY_WITH_TIMEOUT(m->drive(2)->read(0).state == DriveState::Fault, 3000);
        QCOMPARE(m->drive(2)->read(0).fault_code, master_fault::kHeartbeatLost);
        QVERIFY(m->drive(0)->read(0).state == DriveState::Enabled); // the others are untouched
        const CanBusSnapshot snap = m->snapshot();
        QVERIFY2(snap.nodes[2].fault_text.find("heartbeat lost") != std::string::npos,
                 snap.nodes[2].fault_text.c_str());
        bool logged = false;
        for (const MasterEvent& e : m->drainEvents())
            logged = logged ||
                     (e.node == 3 && e.error && e.text.find("heartbeat lost") != std::string::npos);
        QVERIFY(logged);
    }

    void emcyEndsInFaultAndResetRecoversWithoutJump() {
        auto sim = simulator({1, 2}, [](DriveNodeConfig& n) {
            if (n.node == 2) {
                n.faults.fault_code = emcy_code::kDriveOverTemperature;
                n.faults.fault_after_s = 0.2;
            }
        });
        auto m = master(2);
        enableAll(*m);
        QTRY_VERIFY_WITH_TIMEOUT(m->drive(1)->read(0).state == DriveState::Fault, 3000);
        QCOMPARE(m->drive(1)->read(0).fault_code, std::uint32_t(emcy_code::kDriveOverTemperature));
        const CanBusSnapshot snap = m->snapshot();
        QVERIFY2(snap.nodes[1].last_emcy_text.find("excess temperature") != std::string::npos,
                 snap.nodes[1].last_emcy_text.c_str());
        bool logged = false;
        for (const MasterEvent& e : m->drainEvents())
            logged =
                logged || (e.node == 2 && e.error && e.text.find("0x4310") != std::string::npos);
        QVERIFY(logged);
        // Fault reset (rising edge of bit 7), then enable again: the axis holds where it is.
        m->drive(1)->faultReset();
        QTRY_VERIFY_WITH_TIMEOUT(m->drive(1)->read(0).state == DriveState::Disabled, 2000);
        const double before = m->drive(1)->read(0).position;
        m->drive(1)->activate();
        // Set-points written before the drive reported Enabled must not reach it: write a far one.
        m->drive(1)->write(before + 1.0);
        QTRY_VERIFY_WITH_TIMEOUT(m->drive(1)->read(0).state == DriveState::Enabled, 2000);
        for (int k = 0; k < 20; ++k) {
            QTest::qWait(5);
            QVERIFY(std::fabs(sim->snapshot()[1].position_rad - before) < 1e-3);
        }
    }

    void followingErrorEndsInFault() {
        auto sim = simulator({1}, [](DriveNodeConfig& n) { n.faults.torque_loss_after_s = 0.05; });
        auto m = master(1);
        enableAll(*m);
        // Move the axis like the engine would; without torque the following error grows.
        double target = m->drive(0)->read(0).position;
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                const DriveFeedback fb = m->drive(0)->read(0);
                target += 0.002;
                m->drive(0)->write(target);
                return fb.state == DriveState::Fault;
            }(),
            5000);
        QCOMPARE(m->drive(0)->read(0).fault_code, std::uint32_t(emcy_code::kFollowingError));
    }

    void framesOnTheBusAreWellFormed() {
        // An independent listener process sees the traffic too.
        QProcess canbusutil;
        canbusutil.start("/usr/lib/qt6/bin/canbusutil", {"-l", "virtualcan", "can0"});
        QVERIFY(canbusutil.waitForStarted());
        QTest::qWait(300); // its own connection: no signal to wait for from outside
        heard_.clear();
        {
            auto sim = simulator({1, 2});
            auto m = master(2);
            enableAll(*m);
            QTest::qWait(100);
        }
        QTRY_VERIFY(canbusutil.bytesAvailable() > 0 || heard_.size() > 0);
        QTest::qWait(100);
        canbusutil.terminate();
        canbusutil.waitForFinished();
        const QString dump = QString::fromLocal8Bit(canbusutil.readAllStandardOutput());
        qInfo("canbusutil heard:\n%s", qPrintable(dump.left(300)));
        // Its dump lists the frames by COB-ID: the heartbeats of both nodes and the SYNC.
        for (const char* id : {"701", "702", "080"})
            QVERIFY2(dump.contains(QRegularExpression(QString("\\b%1\\b").arg(id))),
                     qPrintable(dump.left(400)));
        QVERIFY(heard_.size() > 50);
        for (const QCanBusFrame& q : heard_) {
            CanFrame f;
            QVERIFY(fromQt(q, f));
            QVERIFY(f.id <= 0x7FF);
            const std::uint32_t fn = cob::functionOf(f.id);
            const int node = cob::nodeOf(f.id);
            int expected = -1;
            if (f.id == cob::kNmt)
                expected = 2;
            else if (f.id == cob::kSync)
                expected = 0;
            else if (fn == cob::kEmcy)
                expected = 8;
            else if (fn == cob::kSdoRx || fn == cob::kSdoTx)
                expected = 8;
            else if (fn == cob::kHeartbeat)
                expected = 1;
            else if (fn == cob::kRpdo1)
                expected = kRpdo1Bytes;
            else if (fn == cob::kRpdo2)
                expected = kRpdo2Bytes;
            else if (fn == cob::kTpdo1)
                expected = kTpdo1Bytes;
            QVERIFY2(expected >= 0, qPrintable(QString("unexpected COB-ID 0x%1").arg(f.id, 0, 16)));
            QVERIFY2(f.len == expected,
                     qPrintable(QString("COB-ID 0x%1 has %2 bytes").arg(f.id, 0, 16).arg(f.len)));
            if (f.id != cob::kNmt && f.id != cob::kSync) QVERIFY(node >= 1 && node <= 2);
        }
    }
};

QTEST_GUILESS_MAIN(CanOpenBusTest)
#include "canopen_bus_test.moc"
