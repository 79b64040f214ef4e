// cutcell-cli over CANopen, end to end between processes: `cutcell-cli drivesim` hosts a
// private virtualcan bus (its own TCP port) with six simulated drives; `cutcell-cli simulate
// --devices canopen` runs the cut against it. Compared with the in-process simulation.
#include "core/job/default_job.h"
#include "devices/canopen/canopen_master.h"

#include "devices/canopen/emcy.h"
#include "devices/canopen/nmt.h"
#include "devices/canopen/pdo.h"
#include "devices/canopen/qt_can_frame.h"
#include "devices/canopen/sdo.h"
#include "devices/canopen/virtualcan_host.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QDeadlineTimer>
#include <QDirIterator>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/support/free_local_port.h"
#include <csignal>
#include <cstdlib>
#include <functional>
#include <memory>
#include <unistd.h>

using namespace cutcell::canopen;

namespace {

// An independent client of the private bus (the test's own QCanBusDevice): every frame with
// the time it arrived (ms since the listener started; the test's event loop must run).
class BusListener : public QObject {
  public:
    struct Heard {
        double t_ms;
        CanFrame f;
    };
    bool connectTo(const QString& interface) {
        hostVirtualCanBus("virtualcan", interface); // not on this thread
        device_.reset(QCanBus::instance()->createDevice("virtualcan", interface));
        if (!device_) return false;
        connect(device_.get(), &QCanBusDevice::framesReceived, this, [this] {
            while (device_->framesAvailable()) {
                CanFrame f;
                if (fromQt(device_->readFrame(), f)) heard.push_back({now(), f});
            }
        });
        clock_.start();
        if (!device_->connectDevice()) return false;
        return QTest::qWaitFor([this] { return device_->state() == QCanBusDevice::ConnectedState; },
                               3000);
    }
    double now() const { return static_cast<double>(clock_.nsecsElapsed()) * 1e-6; }
    bool send(const CanFrame& f) { return device_->writeFrame(toQt(f)); }
    // Last statusword each node reported (TPDO1 or an SDO upload of 0x6041); -1: none.
    int statusword(int node) const {
        for (auto it = heard.rbegin(); it != heard.rend(); ++it) {
            if (cob::nodeOf(it->f.id) != node) continue;
            Tpdo1 t;
            if (decodeTpdo1(it->f, t)) return t.statusword;
            if (cob::functionOf(it->f.id) == cob::kSdoTx) {
                const SdoMessage m = decodeSdo(it->f);
                if (m.kind == SdoKind::UploadResponse && m.address.index == od::kStatusword)
                    return static_cast<int>(m.value & 0xFFFF);
            }
        }
        return -1;
    }
    bool allEnabled(int nodes) const {
        for (int n = 1; n <= nodes; ++n)
            if (statusword(n) < 0 || decodeStatusword(static_cast<std::uint16_t>(statusword(n))) !=
                                         Cia402State::OperationEnabled)
                return false;
        return true;
    }
    size_t count(const std::function<bool(const Heard&)>& match, size_t from = 0) const {
        size_t n = 0;
        for (size_t k = from; k < heard.size(); ++k)
            n += match(heard[k]) ? 1 : 0;
        return n;
    }
    std::vector<Heard> heard;

  private:
    std::unique_ptr<QCanBusDevice> device_;
    QElapsedTimer clock_;
};

} // namespace

class CanOpenCliTest : public QObject {
    Q_OBJECT

    const QString cli_ = QStringLiteral(CUTCELL_CLI);
    const QString job_ = QStringLiteral(CUTCELL_SOURCE_DIR "/resources/jobs/default_job.json");
    // The default job's coupled rigid-body arm without Coulomb friction: over CAN and in process
    // the drives' loops then start the cut from the same settled state, so the bus's effect on
    // the dynamics can be compared to 10 %. (With friction the loops hunt around the first cut
    // point before Start, and each run starts from a different stick-slip state: the max errors
    // then differ by up to 40 % between two runs of the same plant, bus or not - see README,
    // "The arm's mechanics".)
    const QString dynamicsJob_ =
        QStringLiteral(CUTCELL_SOURCE_DIR "/tests/data/robot_rigid_frictionless_job.json");
    QString interface_;
    QTemporaryDir dir_;

    // drivesim in the background, ready when it says so.
    bool startDriveSim(QProcess& p, const QStringList& extra = {}) {
        p.setProgram(cli_);
        p.setArguments(QStringList{"drivesim", "--nodes", "1-6", "--plugin", "virtualcan",
                                   "--interface", interface_} +
                       extra);
        p.start();
        if (!p.waitForStarted()) return false;
        // Ready only when it says so (the line may come in pieces); a silent simulator is not.
        QByteArray said;
        QDeadlineTimer deadline(10000);
        auto ready = [&said] {
            const qsizetype at = said.indexOf("drivesim: ready");
            return at >= 0 && said.indexOf('\n', at) >= 0; // the whole line
        };
        while (!ready()) {
            if (p.state() == QProcess::NotRunning || deadline.hasExpired()) {
                qWarning("drivesim did not get ready: %s%s", said.constData(),
                         p.readAllStandardError().constData());
                return false;
            }
            p.waitForReadyRead(100);
            said += p.readAllStandardOutput();
        }
        return true;
    }
    static void stop(QProcess& p) {
        p.terminate();
        if (!p.waitForFinished(3000)) p.kill();
    }
    // simulate over CAN; returns its exit code, fills stdout/stderr.
    int simulateOverCan(const QString& job, const QStringList& extra, QByteArray& out,
                        QByteArray& err) {
        QProcess p;
        p.start(cli_,
                QStringList{"simulate", job, "--devices", "canopen", "--can-plugin", "virtualcan",
                            "--can-interface", interface_, "--period-ms", "4", "--clock", "fast"} +
                    extra);
        p.waitForFinished(120000);
        out = p.readAllStandardOutput();
        err = p.readAllStandardError();
        return p.exitCode();
    }
    static QJsonObject inProcess(const QString& cli, const QString& job) {
        QProcess p;
        p.start(cli, {"simulate", job});
        p.waitForFinished(120000);
        return QJsonDocument::fromJson(p.readAllStandardOutput()).object();
    }
    // Per axis: |max error over CAN - max error in process| <= 10 % + the position quantum.
    // Over CAN both the target and the actual position travel as whole counts, so each may be
    // off by half a count: one count in all.
    static void compare(const QJsonObject& a, const QJsonObject& b, double countsPerDeg) {
        const QJsonArray ja = a["joints"].toArray(), jb = b["joints"].toArray();
        QCOMPARE(ja.size(), jb.size());
        const double quantum = 1 / countsPerDeg;
        for (int i = 0; i < ja.size(); ++i) {
            const double x = ja[i].toObject()["max_abs_error_deg"].toDouble();
            const double y = jb[i].toObject()["max_abs_error_deg"].toDouble();
            QVERIFY2(
                std::fabs(x - y) <= 0.1 * x + quantum,
                qPrintable(
                    QString("axis %1: in process %2 deg, over CAN %3 deg").arg(i).arg(x).arg(y)));
        }
    }

    // `run JOB --devices canopen` on the private bus with a run log; returns once its events
    // say the torch is on (the cut began). err collects its stderr.
    bool startRunUntilCut(QProcess& run, const QString& runsDir, QByteArray& err) {
        run.start(cli_, {"run", job_, "--devices", "canopen", "--can-plugin", "virtualcan",
                         "--can-interface", interface_, "--period-ms", "4", "--runs", runsDir});
        const bool cutting = QTest::qWaitFor(
            [&] {
                err += run.readAllStandardError();
                return err.contains("torch on") || run.state() == QProcess::NotRunning;
            },
            90000);
        return cutting && err.contains("torch on");
    }
    static bool waitForExit(QProcess& p, QByteArray& err, int ms) {
        const bool ended = QTest::qWaitFor(
            [&] {
                err += p.readAllStandardError();
                return p.state() == QProcess::NotRunning;
            },
            ms);
        err += p.readAllStandardError();
        return ended;
    }
    static QByteArray eventsLog(const QString& runsDir) {
        QByteArray all;
        QDirIterator it(runsDir, {"events.log"}, QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            QFile f(it.next());
            if (f.open(QIODevice::ReadOnly)) all += f.readAll();
        }
        return all;
    }
    // After `from`: every node 1..6 got controlword 0 (disable voltage) on its RPDO2, and an
    // NMT Enter Pre-operational went to all nodes.
    static void expectDisableFramesOnTheBus(const BusListener& bus, size_t from) {
        for (int n = 1; n <= 6; ++n) {
            const size_t disables = bus.count(
                [n](const BusListener::Heard& h) {
                    std::uint16_t c = 0xFFFF;
                    return cob::nodeOf(h.f.id) == n && decodeRpdo2(h.f, c) && c == 0;
                },
                from);
            QVERIFY2(disables >= 1, qPrintable(QString("no disable frame for node %1").arg(n)));
        }
        const size_t preop = bus.count(
            [](const BusListener::Heard& h) {
                NmtCommand c;
                int target = -1;
                return decodeNmt(h.f, c, target) && c == NmtCommand::EnterPreOperational &&
                       target == 0;
            },
            from);
        QVERIFY(preop >= 1);
    }

  private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        interface_ = QString("tcp://127.0.0.1:%1/can0").arg(cutcell::test::freeLocalPort());
    }

    // At 1000 counts/deg the rigid-body arm's errors without friction (~0.001 deg) are one
    // count: the coarse comparison runs on the linear joint plants it was written for (the
    // golden files' job); fineEncodersShowTheSameDynamics compares the coupled arm.
    void linearJobOverCanTracksLikeTheInProcessSimulation() {
        const QString linear =
            QStringLiteral(CUTCELL_SOURCE_DIR "/tests/data/golden/robot_linear_job.json");
        QProcess sim;
        QVERIFY(startDriveSim(sim, {linear}));
        QByteArray out, err;
        const int code = simulateOverCan(linear, {}, out, err);
        stop(sim);
        QVERIFY2(code == 0, err.right(900).constData());
        const QJsonObject can = QJsonDocument::fromJson(out).object();
        QCOMPARE(can["devices"].toObject()["kind"].toString(), QString("canopen"));
        compare(inProcess(cli_, linear), can, 1000);
    }

    void fineEncodersShowTheSameDynamics() {
        // With 100 000 counts/deg quantisation vanishes and the plant/PID dynamics must agree.
        QFile in(dynamicsJob_);
        QVERIFY(in.open(QIODevice::ReadOnly));
        QByteArray text = in.readAll();
        text.replace("\"counts_per_unit\": [1000, 1000, 1000, 1000, 1000, 1000]",
                     "\"counts_per_unit\": [100000, 100000, 100000, 100000, 100000, 100000]");
        const QString fine = dir_.filePath("fine.json");
        QFile f(fine);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text);
        f.close();
        QProcess sim;
        QVERIFY(startDriveSim(sim, {fine}));
        QByteArray out, err;
        const int code = simulateOverCan(fine, {}, out, err);
        stop(sim);
        QVERIFY2(code == 0, err.right(900).constData());
        compare(inProcess(cli_, fine), QJsonDocument::fromJson(out).object(), 100000);
    }

    void emcyFromADriveStopsTheRunWithNodeAndReason() {
        QProcess sim;
        QVERIFY(startDriveSim(
            sim, {"--fault-node", "3", "--fault-code", "0x2310", "--fault-after", "0.5"}));
        QByteArray out, err;
        const int code = simulateOverCan(job_, {}, out, err);
        stop(sim);
        QCOMPARE(code, 1);
        QVERIFY2(err.contains("node 3") && err.contains("0x2310") && err.contains("over-current"),
                 err.constData());
    }

    // Issue 27 (5): a drive that aborts an SDO write of its configuration ends the bring-up at
    // once, naming the node, the object and the abort (it used to wait out 5 s first).
    void anSdoAbortDuringTheBringUpEndsItAtOnce() {
        QProcess sim;
        QVERIFY(startDriveSim(sim, {"--fault-node", "4", "--refuse-object", "0x1017"}));
        QByteArray out, err;
        const int code = simulateOverCan(job_, {}, out, err);
        stop(sim);
        QVERIFY2(code != 0, err.constData());
        QVERIFY2(err.contains("bring-up failed") && err.contains("node 4") &&
                     err.contains("0x1017") && err.contains("0x06090030"),
                 err.constData());
        QVERIFY2(!err.contains("within 5 s"), err.constData());
    }

    // Issue 27 (5): a drive lost mid-cut (its simulator killed; the bus, hosted here, stays)
    // is named: the node, that its process data stopped, and its last heartbeat's age, not
    // only "axis 0: feedback not valid (stale data)".
    void aDriveLostMidCutIsNamedWithItsHeartbeatAge() {
        // A bus of its own: this process hosts it from now on (a host's relay stays for the
        // process's life), so killing the simulator loses only the drives, never the bus; the
        // other tests' bus stays the simulator's.
        const QString shared = interface_;
        interface_ = QString("tcp://127.0.0.1:%1/can0").arg(cutcell::test::freeLocalPort());
        const auto restore = qScopeGuard([&] { interface_ = shared; });
        BusListener bus;
        QVERIFY(bus.connectTo(interface_));
        QProcess sim;
        QVERIFY(startDriveSim(sim));
        QProcess run;
        QByteArray err;
        QVERIFY2(startRunUntilCut(run, dir_.filePath("lost-drive"), err),
                 err.right(900).constData()); // the tail: where it stopped
        sim.kill();
        sim.waitForFinished(5000);
        QVERIFY(waitForExit(run, err, 20000));
        QVERIFY2(run.exitCode() != 0, err.constData());
        const QRegularExpression named(
            "node [1-6]: no process data \\(TPDO\\) for \\d+ ms after a SYNC .*last heartbeat "
            "\\d+ ms ago");
        QVERIFY2(named.match(QString::fromUtf8(err)).hasMatch(), err.constData());
    }

    void heartbeatLossStopsTheRunWithNodeAndReason() {
        QProcess sim;
        QVERIFY(startDriveSim(sim, {"--fault-node", "5", "--heartbeat-stop-after", "0.5"}));
        QByteArray out, err;
        const int code = simulateOverCan(job_, {"--clock", "realtime"}, out, err);
        stop(sim);
        QCOMPARE(code, 1);
        QVERIFY2(err.contains("node 5") && err.contains("heartbeat lost"), err.constData());
    }

    void busLossFaultsEveryDriveAndRecoversWithoutRestart() {
        // The drivesim process hosts the bus; killing it takes the bus away under the master.
        QProcess sim;
        QVERIFY(startDriveSim(sim, {"--nodes", "1-2"}));
        cutcell::Job job = cutcell::defaultJob();
        job.devices.can_interface = interface_.toStdString();
        CanOpenMaster m(masterConfigFromJob(job, 0.004, 2));
        std::string error;
        QVERIFY2(m.start(&error), error.c_str());
        QTRY_VERIFY_WITH_TIMEOUT(m.allOperational(), 5000);
        for (int i = 0; i < 2; ++i)
            m.drive(i)->activate();
        QTRY_VERIFY_WITH_TIMEOUT(m.drive(0)->read(0).state == cutcell::DriveState::Enabled &&
                                     m.drive(1)->read(0).state == cutcell::DriveState::Enabled,
                                 3000);
        sim.kill();
        sim.waitForFinished();
        QTRY_VERIFY_WITH_TIMEOUT(m.drive(0)->read(0).state == cutcell::DriveState::Fault &&
                                     m.drive(1)->read(0).state == cutcell::DriveState::Fault,
                                 3000);
        QCOMPARE(m.drive(0)->read(0).fault_code, master_fault::kBusLost);
        QVERIFY(!m.drive(0)->read(0).feedback_valid);
        const CanBusSnapshot down = m.snapshot();
        QCOMPARE(down.bus, BusState::Disconnected);
        QVERIFY2(down.nodes[1].fault_text.find("connection to the bus lost") != std::string::npos,
                 down.nodes[1].fault_text.c_str());
        // The bus comes back (a new peer hosts it); recover without restarting anything.
        QProcess sim2;
        QVERIFY(startDriveSim(sim2, {"--nodes", "1-2"}));
        m.recoverBus();
        QTRY_VERIFY_WITH_TIMEOUT(m.allOperational(), 5000);
        for (int i = 0; i < 2; ++i) {
            QVERIFY(m.drive(i)->read(0).state ==
                    cutcell::DriveState::Disabled); // not re-enabled by itself
            m.drive(i)->faultReset();
            m.drive(i)->activate();
        }
        QTRY_VERIFY_WITH_TIMEOUT(m.drive(0)->read(0).state == cutcell::DriveState::Enabled &&
                                     m.drive(1)->read(0).state == cutcell::DriveState::Enabled,
                                 3000);
        QCOMPARE(m.snapshot().bus, BusState::Good);
        m.stop();
        stop(sim2);
    }

    void engineRunOverCanCompletes() {
        // cutcell-cli run with the job's devices switched to CANopen by the command line; a
        // shorter cut (15 mm/s) at a 10 ms cycle keeps the test short and the margins wide.
        QFile in(job_);
        QVERIFY(in.open(QIODevice::ReadOnly));
        QByteArray text = in.readAll();
        text.replace("\"speed_mm_s\": 4.397", "\"speed_mm_s\": 15");
        text.replace("\"duration_s\": 30", "\"duration_s\": 1");
        const QString fast = dir_.filePath("fast.json");
        QFile f(fast);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text);
        f.close();
        QProcess sim;
        QVERIFY(startDriveSim(sim));
        QProcess run;
        run.start(cli_, {"run", fast, "--devices", "canopen", "--can-plugin", "virtualcan",
                         "--can-interface", interface_, "--period-ms", "10", "--runs",
                         dir_.filePath("runs"), "--quiet"});
        run.waitForFinished(120000);
        stop(sim);
        const QByteArray err = run.readAllStandardError();
        QVERIFY2(run.exitCode() == 0, err.constData());
        QVERIFY2(err.contains("completed"), err.constData());
        const QJsonArray joints =
            QJsonDocument::fromJson(run.readAllStandardOutput()).object()["joints"].toArray();
        QCOMPARE(joints.size(), 6);
    }

    void sigkillOfTheMasterMidCutStopsEveryDriveByTheMastersHeartbeat() {
        QProcess sim;
        QVERIFY(startDriveSim(sim));
        BusListener bus;
        QVERIFY(bus.connectTo(interface_));
        QProcess run;
        QByteArray err;
        QVERIFY2(startRunUntilCut(run, dir_.filePath("runs-kill"), err),
                 err.right(900).constData());
        QVERIFY(QTest::qWaitFor([&] { return bus.allEnabled(6); }, 2000));
        ::kill(static_cast<pid_t>(run.processId()), SIGKILL); // no code of the master runs
        const double killedAt = bus.now();
        const size_t from = bus.heard.size();
        // Keep the SYNC going and ask every node for its statusword by SDO (a node stops its
        // PDOs when it leaves Operational): the drives' own SYNC watchdog stays quiet, so only
        // their consumer of the master's heartbeat can take them out of Operation Enabled. The
        // SYNC goes on with the master's counter (0x1019), in sequence from its last one: the
        // pacer starts once no SYNC of the master has come for 15 ms (its period is 4 ms), as
        // SYNCs it sent just before the kill may still be on their way (a repeated counter is
        // a 0x8100 EMCY, measured at 30-120 ms after the kill, not the heartbeat's timeout).
        const std::uint8_t overflow = 240; // the job's devices.sync_counter_overflow (default)
        std::uint8_t counter = 0;
        QTimer pacer;
        int tick = 0;
        connect(&pacer, &QTimer::timeout, this, [&] {
            if (counter == 0) {
                double lastSyncMs = -1;
                for (const BusListener::Heard& h : bus.heard)
                    if (std::uint8_t c = 0; decodeSync(h.f, c) && c > 0) {
                        counter = c;
                        lastSyncMs = h.t_ms;
                    }
                if (lastSyncMs < 0 || bus.now() - lastSyncMs < 15) {
                    counter = 0;
                    return;
                }
            }
            counter = nextSyncCounter(counter, overflow);
            bus.send(encodeSync(counter));
            if (tick++ % 2 == 0)
                for (int n = 1; n <= 6; ++n)
                    bus.send(sdoUploadRequest(n, {od::kStatusword, 0}));
        });
        pacer.start(5);
        auto leftOperationEnabled = [&](int n) -> double {
            for (size_t k = from; k < bus.heard.size(); ++k) {
                const BusListener::Heard& h = bus.heard[k];
                if (cob::nodeOf(h.f.id) != n) continue;
                Tpdo1 t;
                std::uint16_t sw = 0;
                bool has = false;
                if (decodeTpdo1(h.f, t)) {
                    sw = t.statusword;
                    has = true;
                } else if (cob::functionOf(h.f.id) == cob::kSdoTx) {
                    const SdoMessage m = decodeSdo(h.f);
                    has = m.kind == SdoKind::UploadResponse && m.address.index == od::kStatusword;
                    sw = static_cast<std::uint16_t>(m.value);
                }
                if (has && decodeStatusword(sw) != Cia402State::OperationEnabled) return h.t_ms;
            }
            return -1;
        };
        const bool allLeft = QTest::qWaitFor(
            [&] {
                for (int n = 1; n <= 6; ++n)
                    if (leftOperationEnabled(n) < 0) return false;
                return true;
            },
            3000);
        pacer.stop();
        run.waitForFinished(3000);
        QVERIFY2(counter > 0, "the master's SYNC carried no counter");
        QVERIFY2(allLeft, "a drive stayed in Operation Enabled after its master was killed");
        double lastBeat = -1;
        for (const BusListener::Heard& h : bus.heard)
            if (h.f.id == cob::kHeartbeat + 127 && h.t_ms <= killedAt) lastBeat = h.t_ms;
        QVERIFY2(lastBeat > 0, "the master produced no heartbeat (0x77F)");
        const double timeoutMs = 300; // the job's devices.heartbeat_timeout_ms
        for (int n = 1; n <= 6; ++n) {
            const double after = leftOperationEnabled(n) - lastBeat;
            qInfo("node %d left Operation Enabled %.0f ms after the master's last heartbeat", n,
                  after);
            // Not before the configured time (it is the heartbeat consumer acting), and within
            // it plus the listener's sampling (SDO every 10 ms) and scheduling: measured 314,
            // 340 and 401 ms on this 2-core host at load 17.
            QVERIFY2(after >= 0.9 * timeoutMs && after <= timeoutMs + 150,
                     qPrintable(QString("node %1: %2 ms").arg(n).arg(after)));
            const size_t emcy = bus.count(
                [n](const BusListener::Heard& h) {
                    Emcy e;
                    return decodeEmcy(h.f, e) && e.node == n &&
                           e.error_code == emcy_code::kHeartbeat;
                },
                from);
            QVERIFY2(emcy == 1, qPrintable(QString("node %1: %2 EMCY 0x8130").arg(n).arg(emcy)));
        }
        stop(sim);
    }

    void sigtermOfARunTakesTheTorchOffAndDisablesEveryDriveThenLogs() {
        QProcess sim;
        QVERIFY(startDriveSim(sim));
        BusListener bus;
        QVERIFY(bus.connectTo(interface_));
        QProcess run;
        QByteArray err;
        const QString runs = dir_.filePath("runs-term");
        QVERIFY2(startRunUntilCut(run, runs, err), err.right(900).constData());
        const size_t from = bus.heard.size();
        run.terminate(); // SIGTERM
        QVERIFY(waitForExit(run, err, 5000));
        stop(sim);
        QCOMPARE(run.exitStatus(), QProcess::NormalExit);
        QCOMPARE(run.exitCode(), 128 + SIGTERM);
        expectDisableFramesOnTheBus(bus, from);
        QVERIFY2(err.contains("program ending (SIGTERM): torch off, 6 drives disabled"),
                 err.constData());
        const QByteArray log = eventsLog(runs);
        QVERIFY2(log.contains("program ending (SIGTERM): torch off, 6 drives disabled"),
                 log.constData());
    }

    void sigintOfASimulationOverCanDisablesEveryDrive() {
        QProcess sim;
        QVERIFY(startDriveSim(sim));
        BusListener bus;
        QVERIFY(bus.connectTo(interface_));
        QProcess p;
        p.start(cli_, {"simulate", job_, "--devices", "canopen", "--can-plugin", "virtualcan",
                       "--can-interface", interface_, "--period-ms", "4", "--clock", "realtime"});
        QVERIFY(QTest::qWaitFor([&] { return bus.allEnabled(6); }, 20000));
        const size_t from = bus.heard.size();
        ::kill(static_cast<pid_t>(p.processId()), SIGINT);
        QByteArray err;
        QVERIFY(waitForExit(p, err, 5000));
        stop(sim);
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 128 + SIGINT);
        expectDisableFramesOnTheBus(bus, from);
        QVERIFY2(err.contains("program ending (SIGINT)"), err.constData());
    }

  private:
    // A cell under a running master; a second master (`run`) must refuse the bus and write
    // nothing. firstEnded: the first master ended before the second had finished, so the
    // scenario did not happen (its stderr says why: seen once in CI, where a loaded host held
    // the bus's frames past the 100 ms the engine allows process data to be late).
    void secondMasterAttempt(QString& firstEnded) {
        QProcess sim;
        QVERIFY(startDriveSim(sim));
        BusListener bus;
        QVERIFY(bus.connectTo(interface_));
        QProcess first;
        first.start(cli_,
                    {"simulate", job_, "--devices", "canopen", "--can-plugin", "virtualcan",
                     "--can-interface", interface_, "--period-ms", "4", "--clock", "realtime"});
        QVERIFY(QTest::qWaitFor([&] { return bus.allEnabled(6); }, 20000));
        const size_t from = bus.heard.size();
        QProcess second;
        second.start(cli_, {"run", job_, "--devices", "canopen", "--can-plugin", "virtualcan",
                            "--can-interface", interface_, "--period-ms", "4", "--quiet"});
        QByteArray err;
        QVERIFY2(waitForExit(second, err, 20000), err.right(900).constData());
        QCOMPARE(second.exitCode(), 1);
        QVERIFY2(err.contains("another CANopen master is active") && err.contains("SYNC (0x080)"),
                 err.constData());
        if (first.state() != QProcess::Running) {
            first.waitForFinished(1000);
            firstEnded = QString("exit code %1; its stderr:\n%2")
                             .arg(first.exitCode())
                             .arg(QString::fromLocal8Bit(first.readAllStandardError().right(1500)));
            stop(sim);
            return;
        }
        // It wrote nothing: the first master's cell is still enabled.
        QCOMPARE(bus.count([](const BusListener::Heard& h) { return h.f.id == cob::kNmt; }, from),
                 size_t(0));
        QVERIFY(QTest::qWaitFor([&] { return bus.allEnabled(6); }, 1000));
        QVERIFY2(first.state() == QProcess::Running,
                 first.readAllStandardError().right(1500).constData());
        first.terminate();
        QByteArray ignored;
        waitForExit(first, ignored, 5000);
        stop(sim);
    }

  private slots:
    void aSecondMasterRefusesTheBusNamingWhatItHeard() {
        // A second attempt only when the first master ended on its own before the second was
        // done (printed); every check holds on an attempt where the scenario happened.
        for (int attempt = 1; attempt <= 2; ++attempt) {
            QString firstEnded;
            secondMasterAttempt(firstEnded);
            if (QTest::currentTestFailed() || firstEnded.isEmpty()) return;
            qWarning("attempt %d: the first master ended before the second was done: %s", attempt,
                     qPrintable(firstEnded));
        }
        QFAIL("the first master ended on its own in both attempts (see the warnings)");
    }

    void anInterfaceThePluginDoesNotOfferIsRefusedListingItsOwn() {
        const QString wrong = QString(interface_).replace("/can0", "/can5");
        QProcess p;
        p.start(cli_, {"simulate", job_, "--devices", "canopen", "--can-plugin", "virtualcan",
                       "--can-interface", wrong, "--period-ms", "4"});
        QByteArray err;
        QVERIFY(waitForExit(p, err, 20000));
        QCOMPARE(p.exitCode(), 1);
        QVERIFY2(err.contains("is not offered by plugin virtualcan; it offers: can0, can1"),
                 err.constData());
        QProcess d;
        d.start(cli_, {"drivesim", "--plugin", "virtualcan", "--interface", "can5"});
        err.clear();
        QVERIFY(waitForExit(d, err, 20000));
        QCOMPARE(d.exitCode(), 1);
        QVERIFY2(err.contains("it offers: can0, can1"), err.constData());
    }

    void aDriveFaultDuringTheApproachStopsTheSimulationAtOnce() {
        QProcess sim;
        QVERIFY(startDriveSim(
            sim, {"--fault-node", "3", "--fault-code", "0x2310", "--fault-after", "0.1"}));
        BusListener bus;
        QVERIFY(bus.connectTo(interface_));
        QProcess p;
        p.start(cli_, {"simulate", job_, "--devices", "canopen", "--can-plugin", "virtualcan",
                       "--can-interface", interface_, "--period-ms", "4", "--clock", "realtime"});
        QByteArray err;
        QVERIFY(waitForExit(p, err, 60000));
        stop(sim);
        QCOMPARE(p.exitCode(), 1);
        // The master's EMCY line names the node and the reason, the engine's fault event the
        // axis behind it (node 3 = axis 2) and the state the fault ended (the cut's approach
        // runs in Running).
        QVERIFY2(err.contains("node 3: EMCY 0x2310") && err.contains("over-current") &&
                     err.contains("Running -> Fault") &&
                     err.contains("axis 2 (theta2): drive fault 0x2310"),
                 err.constData());
        // After node 3's EMCY every other axis is disabled (controlword 0 on its RPDO2) after
        // at most the set-points already on their way (the RPDO1 of the cycle in progress and
        // of the one that saw the fault), not seconds more of the approach. The RPDO1s after
        // the disable are the master's until the process ends and carry the drive's own
        // position (a disabled drive's target: no motion).
        size_t emcyAt = 0;
        for (size_t k = 0; k < bus.heard.size() && !emcyAt; ++k) {
            Emcy e;
            if (decodeEmcy(bus.heard[k].f, e) && e.node == 3 && e.error_code == 0x2310) emcyAt = k;
        }
        QVERIFY(emcyAt > 0);
        for (int n : {1, 2, 4, 5, 6}) {
            size_t disableAt = 0, before = 0, after = 0;
            long long actual = 0, farthest = 0; // counts: last TPDO1; |target - actual|
            for (size_t k = 0; k < bus.heard.size(); ++k) {
                const CanFrame& f = bus.heard[k].f;
                if (cob::nodeOf(f.id) != n) continue;
                std::uint16_t c = 0xFFFF;
                Rpdo1 r;
                Tpdo1 t;
                if (decodeTpdo1(f, t)) actual = t.actual_counts;
                if (k < emcyAt) continue;
                if (!disableAt && decodeRpdo2(f, c) && c == 0) disableAt = k;
                if (!decodeRpdo1(f, r)) continue;
                ++(disableAt ? after : before);
                if (disableAt) farthest = std::max(farthest, std::llabs(r.target_counts - actual));
            }
            QVERIFY2(disableAt > 0, qPrintable(QString("node %1 was not disabled").arg(n)));
            qInfo("node %d: %zu set-points between the EMCY and its disable, %zu after, at most "
                  "%lld counts from the drive's position",
                  n, before, after, static_cast<long long>(farthest));
            QVERIFY2(farthest <= 1, qPrintable(QString("node %1: a target %2 counts away after "
                                                       "its disable")
                                                   .arg(n)
                                                   .arg(farthest)));
            QVERIFY2(before <= 2, qPrintable(QString("node %1 got %2 set-points after the fault, "
                                                     "before its disable")
                                                 .arg(n)
                                                 .arg(before)));
        }
    }

    // The run log names the node and the decoded reason of a device fault during a cut.
    void runLogNamesTheNodeAndTheReasonOfAnEmcy() {
        QProcess sim;
        // The fault comes by SIGUSR1 at the moment chosen below (its timer: never).
        QVERIFY(startDriveSim(
            sim, {"--fault-node", "3", "--fault-code", "0x2310", "--fault-after", "1000000"}));
        const QString runs = dir_.filePath("runs-emcy");
        QProcess run;
        QByteArray err;
        QVERIFY2(startRunUntilCut(run, runs, err), err.right(900).constData());
        ::kill(static_cast<pid_t>(sim.processId()), SIGUSR1); // node 3 faults now
        QVERIFY(waitForExit(run, err, 10000));
        stop(sim);
        QCOMPARE(run.exitCode(), 1);
        const QByteArray log = eventsLog(runs);
        QVERIFY2(log.contains("node 3: EMCY 0x2310") && log.contains("over-current"),
                 log.constData());
    }

    void runLogNamesTheNodeWhoseHeartbeatWasLost() {
        QProcess sim;
        QVERIFY(startDriveSim(sim, {"--fault-node", "2"}));
        const QString runs = dir_.filePath("runs-heartbeat");
        QProcess run;
        QByteArray err;
        QVERIFY2(startRunUntilCut(run, runs, err), err.right(900).constData());
        ::kill(static_cast<pid_t>(sim.processId()), SIGUSR2); // node 2's heartbeats stop
        QVERIFY(waitForExit(run, err, 10000));
        stop(sim);
        QCOMPARE(run.exitCode(), 1);
        const QByteArray log = eventsLog(runs);
        QVERIFY2(log.contains("node 2: heartbeat lost"), log.constData());
    }

    void runLogSaysTheBusWasLost() {
        QProcess sim; // hosts the bus: killing it takes the bus away
        QVERIFY(startDriveSim(sim));
        const QString runs = dir_.filePath("runs-bus");
        QProcess run;
        QByteArray err;
        QVERIFY2(startRunUntilCut(run, runs, err), err.right(900).constData());
        sim.kill();
        sim.waitForFinished();
        QVERIFY(waitForExit(run, err, 10000));
        QCOMPARE(run.exitCode(), 1);
        const QByteArray log = eventsLog(runs);
        QVERIFY2(log.contains("CAN bus: connection to the bus lost"), log.constData());
    }

    void tooShortCycleIsRefusedWithFigures() {
        QByteArray out, err;
        QProcess p;
        p.start(cli_, {"simulate", job_, "--devices", "canopen", "--can-interface", interface_,
                       "--period-ms", "1"});
        p.waitForFinished(30000);
        err = p.readAllStandardError();
        QCOMPARE(p.exitCode(), 1);
        QVERIFY2(err.contains("13 frames") && err.contains("use a period >="), err.constData());
    }

    void badArgumentsNameTheValue() {
        QProcess p;
        p.start(cli_, {"drivesim", "--nodes", "0-200"});
        p.waitForFinished(10000);
        QCOMPARE(p.exitCode(), 64);
        QVERIFY(p.readAllStandardError().contains("--nodes = \"0-200\""));
        p.start(cli_, {"simulate", job_, "--devices", "cann"});
        p.waitForFinished(10000);
        QCOMPARE(p.exitCode(), 64);
        QVERIFY(p.readAllStandardError().contains("--devices = \"cann\""));
    }
};

QTEST_GUILESS_MAIN(CanOpenCliTest)
#include "canopen_cli_test.moc"
