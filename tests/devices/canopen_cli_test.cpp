// cutcell-cli over CANopen, end to end between processes: `cutcell-cli drivesim` hosts a
// private virtualcan bus (its own TCP port) with six simulated drives; `cutcell-cli simulate
// --devices canopen` runs the cut against it. Compared with the in-process simulation.
#include "core/job/default_job.h"
#include "devices/canopen/canopen_master.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <unistd.h>

using namespace cutcell::canopen;

class CanOpenCliTest : public QObject {
    Q_OBJECT

    const QString cli_ = QStringLiteral(CUTCELL_CLI);
    const QString job_ = QStringLiteral(CUTCELL_SOURCE_DIR "/resources/jobs/default_job.json");
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
        for (int i = 0; i < 100 && !p.readAllStandardOutput().contains("drivesim: ready"); ++i) {
            if (p.state() == QProcess::NotRunning) return false;
            p.waitForReadyRead(100);
        }
        return p.state() == QProcess::Running;
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

  private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        interface_ = QString("tcp://127.0.0.1:%1/can0").arg(40000 + (getpid() % 20000));
    }

    void defaultJobOverCanTracksLikeTheInProcessSimulation() {
        QProcess sim;
        QVERIFY(startDriveSim(sim));
        QByteArray out, err;
        const int code = simulateOverCan(job_, {}, out, err);
        stop(sim);
        QVERIFY2(code == 0, err.constData());
        const QJsonObject can = QJsonDocument::fromJson(out).object();
        QCOMPARE(can["devices"].toObject()["kind"].toString(), QString("canopen"));
        compare(inProcess(cli_, job_), can, 1000);
    }

    void fineEncodersShowTheSameDynamics() {
        // With 100 000 counts/deg quantisation vanishes and the plant/PID dynamics must agree.
        QFile in(job_);
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
        QVERIFY2(code == 0, err.constData());
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
