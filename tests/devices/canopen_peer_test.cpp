// The CANopen master against a stack written by someone else: the npm package `canopen` (a
// CiA 301 device: SDO server, NMT, heartbeat producer and consumer, EMCY, PDOs), run by Node.js
// as tests/peer/canopen_peer.js and bridged to a private virtualcan bus hosted by this test.
// Checks SDO reads and writes of its dictionary (the master's whole start-up), NMT start and
// stop, its heartbeat seen and its loss detected, an EMCY decoded, and PDOs mapped by the
// master carrying its statusword and position. Skipped (exit 77) when Node.js or the npm
// package is missing (tools/peer_deps.sh installs it).
#include "devices/canopen/canopen_master.h"
#include "devices/canopen/emcy.h"
#include "devices/canopen/virtualcan_host.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QtTest>

#include "tests/support/free_local_port.h"
#include <cmath>
#include <cstdio>
#include <memory>
#include <unistd.h>

using namespace cutcell;
using namespace cutcell::canopen;

namespace {

constexpr int kPeerNode = 10;
constexpr int kSkip = 77;
const QString kPeerDir = QStringLiteral(CUTCELL_SOURCE_DIR "/tests/peer");

} // namespace

class CanOpenPeerTest : public QObject {
    Q_OBJECT

    QString interface_;
    int port_ = 0;
    std::unique_ptr<QCanBusDevice> host_; // hosts the private bus
    std::unique_ptr<QProcess> peer_;
    QByteArray said_; // the peer's stdout so far
    std::unique_ptr<CanOpenMaster> master_;

    bool peerSaid(const QByteArray& line) {
        said_ += peer_->readAllStandardOutput();
        return said_.contains(line);
    }
    void tell(const QByteArray& command) {
        peer_->write(command + '\n');
        peer_->waitForBytesWritten(1000);
    }
    QJsonObject dump() {
        const qsizetype from = said_.size();
        tell("dump");
        QJsonObject od;
        [[maybe_unused]] const bool answered = QTest::qWaitFor(
            [&] {
                said_ += peer_->readAllStandardOutput();
                const qsizetype at = said_.indexOf("od {", from);
                const qsizetype end = at < 0 ? -1 : said_.indexOf('\n', at);
                if (end < 0) return false;
                od = QJsonDocument::fromJson(said_.mid(at + 3, end - at - 3)).object();
                return true;
            },
            3000);
        return od;
    }
    CanOpenMasterConfig config() const {
        CanOpenMasterConfig c;
        c.interface = interface_;
        c.period_s = 0.01;
        c.heartbeat_timeout_s = 0.3;
        c.nodes = {{kPeerNode, 1000, false}};
        return c;
    }
    bool eventSeen(const std::string& text, std::vector<MasterEvent>& seen) {
        for (const MasterEvent& e : master_->drainEvents())
            seen.push_back(e);
        for (const MasterEvent& e : seen)
            if (e.text.find(text) != std::string::npos) return true;
        return false;
    }

  private slots:
    void initTestCase() {
        port_ = cutcell::test::freeLocalPort();
        interface_ = QString("tcp://127.0.0.1:%1/can0").arg(port_);
        hostVirtualCanBus("virtualcan", interface_); // not on this thread
        host_.reset(QCanBus::instance()->createDevice("virtualcan", interface_));
        QVERIFY(host_ && host_->connectDevice());
        QTRY_COMPARE(host_->state(), QCanBusDevice::ConnectedState);
    }

    void init() {
        said_.clear();
        peer_ = std::make_unique<QProcess>();
        peer_->setWorkingDirectory(kPeerDir);
        peer_->setProcessChannelMode(QProcess::SeparateChannels);
        peer_->start("node", {"canopen_peer.js", "--port", QString::number(port_), "--id",
                              QString::number(kPeerNode)});
        QVERIFY(peer_->waitForStarted());
        QVERIFY2(QTest::qWaitFor([&] { return peerSaid("ready\n"); }, 10000),
                 (said_ + peer_->readAllStandardError()).constData());
        master_ = std::make_unique<CanOpenMaster>(config());
        std::string error;
        QVERIFY2(master_->start(&error), error.c_str());
        QVERIFY2(QTest::qWaitFor([&] { return master_->allOperational(); }, 5000),
                 master_->snapshot().nodes[0].fault_text.c_str());
    }

    void cleanup() {
        master_.reset();
        if (peer_) {
            peer_->write("quit\n");
            if (!peer_->waitForFinished(2000)) peer_->kill();
            peer_->waitForFinished();
        }
        peer_.reset();
    }

    // Start-up: SDO read of 0x1000 (profile 402 accepted), SDO writes of the cycle, the mode,
    // the heartbeats, the abort connection option and the PDO mappings (CiA 301 procedure),
    // NMT start; the peer's own stack confirms each value in its dictionary.
    void theMasterConfiguresThePeersDictionaryBySdo() {
        QVERIFY(peerSaid("nmt OPERATIONAL"));
        const QJsonObject od = dump();
        QCOMPARE(od["cycle_period_us"].toInt(), 10000);
        QCOMPARE(od["mode"].toInt(), 8);
        QCOMPARE(od["producer_heartbeat_ms"].toInt(), 100);
        QCOMPARE(od["consumer_heartbeat"].toInteger(), (127 << 16) | 300);
        QCOMPARE(od["abort_connection_option"].toInt(), 3);
        QCOMPARE(od["tpdo1_cob_id"].toInteger(), 0x180 + kPeerNode); // valid again
        QCOMPARE(od["tpdo1_type"].toInt(), 1);                       // every SYNC
        const QJsonArray tpdo = od["tpdo1_map"].toArray();
        QCOMPARE(tpdo.size(), 3);
        QCOMPARE(tpdo[0].toInteger(), 0x60410010);
        QCOMPARE(tpdo[1].toInteger(), 0x60640020);
        QCOMPARE(tpdo[2].toInteger(), 0x60770010);
        QCOMPARE(od["rpdo2_map"].toArray().size(), 1);
        const CanNodeSnapshot n = master_->snapshot().nodes[0];
        QVERIFY(n.configured);
        QCOMPARE(n.nmt, NmtState::Operational);
        QVERIFY(n.heartbeat_age_ms >= 0 && n.heartbeat_age_ms < 300);
    }

    // The PDOs the master mapped: controlwords on RPDO1 walk the peer's power state machine
    // to Operation Enabled, and its TPDO1 (statusword, position) reaches the drive's read().
    void pdosMappedByTheMasterCarryStatusAndPosition() {
        CanOpenDrive* d = master_->drive(0);
        d->activate();
        QVERIFY2(QTest::qWaitFor(
                     [&] {
                         const DriveFeedback fb = d->read(0);
                         d->write(fb.position);
                         return fb.state == DriveState::Enabled;
                     },
                     3000),
                 said_.constData());
        QVERIFY(peerSaid("controlword 0x000F"));
        tell("position 12345");
        QVERIFY(QTest::qWaitFor(
            [&] { return std::lround(d->read(0).position * d->countsPerAxisUnit()) == 12345; },
            2000));
        QCOMPARE(d->read(0).state, DriveState::Enabled);
    }

    void anEmcyOfThePeerIsDecoded() {
        std::vector<MasterEvent> seen;
        tell("emcy 0x2310");
        QVERIFY2(QTest::qWaitFor([&] { return eventSeen("node 10: EMCY 0x2310", seen); }, 2000),
                 seen.empty() ? "no event" : seen.back().text.c_str());
        QVERIFY2(seen.back().text.find("over-current") != std::string::npos, // decoded
                 seen.back().text.c_str());
        QCOMPARE(master_->snapshot().nodes[0].last_emcy_code, std::uint16_t(0x2310));
    }

    void theLossOfThePeersHeartbeatIsDetected() {
        QCOMPARE(master_->drive(0)->read(0).state, DriveState::Disabled);
        tell("heartbeat off");
        QVERIFY(QTest::qWaitFor(
            [&] { return master_->drive(0)->read(0).state == DriveState::Fault; }, 2000));
        QCOMPARE(master_->drive(0)->read(0).fault_code, master_fault::kHeartbeatLost);
        const std::string why = master_->snapshot().nodes[0].fault_text;
        QVERIFY2(why.find("heartbeat lost") != std::string::npos, why.c_str());
    }

    // NMT: the master's stop puts the peer into pre-operational; then the peer's own consumer of
    // the master's heartbeat (configured by the master through 0x1016) notices the master gone.
    void nmtStopAndTheMastersHeartbeatWatchedByThePeer() {
        QVERIFY(peerSaid("nmt OPERATIONAL"));
        const qsizetype before = said_.size();
        master_->stop();
        QVERIFY(QTest::qWaitFor(
            [&] {
                peerSaid("");
                return said_.indexOf("nmt PRE_OPERATIONAL", before) >= 0;
            },
            2000));
        QVERIFY2(QTest::qWaitFor([&] { return peerSaid("heartbeat-timeout 127"); }, 2000),
                 said_.constData());
    }
};

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    const QString node = QStandardPaths::findExecutable("node");
    if (node.isEmpty() || !QFile::exists(kPeerDir + "/node_modules/canopen/package.json")) {
        std::printf("SKIP: %s (run tools/peer_deps.sh)\n",
                    node.isEmpty() ? "Node.js is not installed"
                                   : "the npm package canopen is not installed in tests/peer");
        return kSkip;
    }
    CanOpenPeerTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "canopen_peer_test.moc"
