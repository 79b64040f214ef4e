// The operator station's side of the shop floor (issue 26, app/gui/shopfloor_station.*): a job
// the network queues is validated on the link's thread (a bad one is refused with the job
// reader's own message and never reaches the queue), arrives in the GUI's queue, and becomes
// the job being edited only when the operator opens it (nothing starts it); the queue can be
// cleared from the network; a remote feed hold reaches the run controller. The link's settings
// (app/gui/shopfloor_settings.*): a bad value is refused with the checker's message and nothing
// written; a good one is written atomically, reads back equal, restarts the link and leaves one
// audit event per changed key; "Link settings…" needs the engineer level where users exist and
// edits the default file when the link is off.
#include "main_window_run.h"
#include "shopfloor_settings.h"
#include "shopfloor_station.h"
#include "sim_rig.h"
#include "station_access.h"

#include "core/job/job_io.h"
#include "devices/record/audit_trail.h"
#include "devices/record/user_directory.h"
#include "devices/shopfloor/shopfloor_config.h"
#include "ui/access_control.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/number_fields.h"
#include "ui/job_queue.h"
#include "ui/main_window.h"
#include "ui/panels/job_queue_panel.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

using cutcell::UserLevel;
using cutcell::app::ShopfloorSettingsDialog;
using CutCell::ui::AccessControl;
using CutCell::ui::JobQueue;
using CutCell::ui::JobQueuePanel;
using CutCell::ui::MainWindow;

namespace {

// The trail as a list (single-user access with this sink: the desktop user is the actor).
struct RecordingSink : cutcell::AuditSink {
    std::vector<cutcell::AuditEvent> events;
    void append(const cutcell::AuditEvent& e) override { events.push_back(e); }
};

template <class T> T* field(QWidget& dialog, const char* name) {
    T* f = dialog.findChild<T*>(name);
    if (!f) qFatal("no field %s", name);
    return f;
}

std::vector<std::string> filesIn(const QString& folder) {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(folder.toStdString()))
        out.push_back(e.path().filename().string());
    return out;
}

} // namespace

class TestShopfloorStation : public QObject {
    Q_OBJECT
    QTemporaryDir config_; // $XDG_CONFIG_HOME: the default file goes here, not to the home

    // As the link does: the call on another thread, its answer back.
    static std::string fromNetwork(const std::string& text) {
        cutcell::app::StationCommands commands;
        std::string answer;
        std::thread t([&] { answer = commands.queueJob(text, "spBv1.0/shop/NCMD/cell-1"); });
        t.join();
        return answer;
    }
    static std::string shippedJob(const char* file) {
        return cutcell::readTextFile(std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/" + file);
    }

  private slots:
    void initTestCase() {
        QVERIFY(config_.isValid());
        qputenv("XDG_CONFIG_HOME", config_.path().toUtf8());
    }
    void cleanupTestCase() {
        cutcell::app::closeStationAccess();
        cutcell::app::closeShopfloor();
    }

    void aQueuedJobWaitsForTheOperator() {
        JobQueue* queue = cutcell::app::stationJobQueue();
        queue->clear();
        MainWindow w(nullptr);
        const std::string before = w.editor()->job().name;
        QCOMPARE(fromNetwork(shippedJob("plasma_hole_job.json")), std::string());
        QTRY_COMPARE(queue->size(), 1);
        QVERIFY(queue->entries()[0].source.contains("shop floor"));
        QVERIFY(queue->entries()[0].source.contains("NCMD/cell-1"));
        // Queued, not opened and not started: the window's job is still its own.
        QCOMPARE(w.editor()->job().name, before);
        JobQueuePanel panel(queue, w.document());
        QCOMPARE(panel.table()->rowCount(), 1);
        QCOMPARE(panel.table()->item(0, 0)->text().toStdString(),
                 cutcell::parseJob(shippedJob("plasma_hole_job.json")).name);
        QString why;
        QVERIFY2(panel.openQueued(0, &why), qPrintable(why));
        QCOMPARE(w.editor()->job().name,
                 cutcell::parseJob(shippedJob("plasma_hole_job.json")).name);
        QVERIFY(w.editor()->job().process.used);
        QCOMPARE(queue->size(), 0);
        QCOMPARE(panel.table()->rowCount(), 0);
    }

    // What the station publishes: after a completed run its figures (from the run's summary,
    // told by the engine's logger thread) and what was made; after an E-STOP the active alarm.
    void theSnapshotCarriesTheRunAndItsAlarms() {
        MainWindow w(&cutcell::app::makeRig);
        QString why;
        QVERIFY2(autoRunCompletes(w, 120000, &why), qPrintable(why + "\n" + lastLog(w)));
        QTRY_VERIFY_WITH_TIMEOUT(cutcell::app::stationSnapshot(w).last_run.has_value(), 10000);
        const cutcell::shopfloor::CellSnapshot s = cutcell::app::stationSnapshot(w);
        QCOMPARE(s.state, std::string("Completed"));
        QCOMPARE(s.last_run->outcome, std::string("completed"));
        QCOMPARE(s.last_run->error_unit, std::string("deg")); // the robot's joints are rotary
        QVERIFY(std::isfinite(s.last_run->tracking_max) && s.last_run->tracking_max > 0);
        QVERIFY(s.last_run->tracking_rms > 0 &&
                s.last_run->tracking_rms <= s.last_run->tracking_max);
        QVERIFY(s.last_run->cycle_time_s > 0);
        QCOMPARE(s.pieces_made, static_cast<std::uint64_t>(w.run()->partsCompleted()));
        QVERIFY(s.pieces_made >= 1);
        QVERIFY(s.alarms.empty());
        QCOMPARE(s.axes.size(), std::size_t{6});
        w.run()->emergencyStop();
        QTRY_VERIFY_WITH_TIMEOUT(!cutcell::app::stationSnapshot(w).alarms.empty(), 10000);
        const std::string alarm = cutcell::app::stationSnapshot(w).alarms.front();
        QVERIFY2(alarm.find("operator") != std::string::npos, alarm.c_str());
    }

    void aBadJobIsRefusedWithTheReadersMessage() {
        JobQueue* queue = cutcell::app::stationJobQueue();
        queue->clear();
        const std::string bad = R"({"schema": 2, "name": "x", "machine": {"kind": "no_such"}})";
        std::string expected;
        try {
            cutcell::parseJob(bad);
        } catch (const cutcell::JobError& e) {
            expected = e.what();
        }
        QVERIFY(!expected.empty());
        QCOMPARE(fromNetwork(bad), expected);
        // A job that reads but is not valid: the first issue with its key.
        std::string text = shippedJob("default_job.json");
        const auto at = text.find("\"speed_mm_s\": 4.397");
        QVERIFY(at != std::string::npos);
        text.replace(at, 19, "\"speed_mm_s\": 900");
        const std::string answer = fromNetwork(text);
        for (const char* part : {"cut.speed_mm_s", "900", "mm/s", "500"})
            QVERIFY2(answer.find(part) != std::string::npos, answer.c_str());
        QCoreApplication::processEvents();
        QCOMPARE(queue->size(), 0);
    }

    void theNetworkClearsTheQueue() {
        JobQueue* queue = cutcell::app::stationJobQueue();
        queue->clear();
        QCOMPARE(fromNetwork(shippedJob("default_job.json")), std::string());
        QCOMPARE(fromNetwork(shippedJob("profile_cutter_job.json")), std::string());
        QTRY_COMPARE(queue->size(), 2);
        std::thread t([] { cutcell::app::StationCommands().clearQueue(); });
        t.join();
        QTRY_COMPARE(queue->size(), 0);
    }

    // A bad value: the checker's message (key, value, unit, limit) in the dialog, the field
    // marked, nothing written, nothing audited, the link left alone.
    void theSettingsRefuseABadValue() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("shopfloor.json").toStdString();
        RecordingSink sink;
        AccessControl access(nullptr, &sink, "tester");
        int restarts = 0;
        ShopfloorSettingsDialog d(path, &access, [&] {
            ++restarts;
            return std::string("restarted");
        });
        auto* problem = field<QLabel>(d, "shopfloorSettingsProblem");
        auto* port = field<QSpinBox>(d, "shopfloorPort");
        const auto refused = [&](std::initializer_list<const char*> parts) {
            field<QPushButton>(d, "shopfloorSettingsSave")->click();
            QVERIFY(problem->isVisibleTo(&d));
            for (const char* part : parts)
                QVERIFY2(problem->text().contains(part), qPrintable(problem->text()));
            QVERIFY(!std::filesystem::exists(path));
            QCOMPARE(filesIn(dir.path()).size(), size_t{0});
        };
        port->setValue(70000);
        refused({"port", "70000", "65535"});
        QVERIFY(port->property("invalid").toBool());
        port->setValue(8883);
        field<QLineEdit>(d, "shopfloorGroupId")->setText("cutting");
        field<QLineEdit>(d, "shopfloorEdgeNodeId")->setText("cell/7");
        refused({"edge_node_id", "cell/7", "'/'"});
        QVERIFY(!port->property("invalid").toBool());
        QVERIFY(field<QLineEdit>(d, "shopfloorEdgeNodeId")->property("invalid").toBool());
        field<QLineEdit>(d, "shopfloorEdgeNodeId")->setText("cell-7");
        field<QDoubleSpinBox>(d, "shopfloorAxisRate")->setValue(20);
        refused({"axis_rate_hz", "20", "Hz", "10"});
        field<QDoubleSpinBox>(d, "shopfloorAxisRate")->setValue(10);
        field<QCheckBox>(d, "shopfloorEnabled")->setChecked(true);
        field<QLineEdit>(d, "shopfloorHost")->setText("broker.shop.lan");
        refused({"tls.ca_file", "missing"});
        QCOMPARE(restarts, 0);
        QVERIFY(sink.events.empty());
        QVERIFY(field<QLabel>(d, "shopfloorSettingsResult")->text().isEmpty());
    }

    // A good save: the file reads back equal (numbers in C notation on a German desktop), no
    // temporary left beside it, the link restarted and its line shown, one audit event per
    // changed key; the next dialog shows the file and audits only what it changes.
    void aGoodSaveReadsBackAndIsAudited() {
        const QLocale before;
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        QTemporaryDir dir;
        const std::string path = dir.filePath("shopfloor.json").toStdString();
        RecordingSink sink;
        AccessControl access(nullptr, &sink, "tester");
        int restarts = 0;
        const auto restart = [&] {
            ++restarts;
            return std::string("shop floor: restarted");
        };
        {
            ShopfloorSettingsDialog d(path, &access, restart);
            field<QCheckBox>(d, "shopfloorEnabled")->setChecked(true);
            field<QLineEdit>(d, "shopfloorHost")->setText("broker.shop.lan");
            field<QSpinBox>(d, "shopfloorPort")->setValue(8884);
            field<QLineEdit>(d, "shopfloorGroupId")->setText("cutting");
            field<QLineEdit>(d, "shopfloorEdgeNodeId")->setText("cell-07");
            field<QLineEdit>(d, "shopfloorUsername")->setText("cell-07");
            field<QLineEdit>(d, "shopfloorPasswordFile")->setText("broker.password");
            field<QLineEdit>(d, "shopfloorCaFile")->setText("shop-ca.crt");
            field<QLineEdit>(d, "shopfloorCertFile")->setText("cell.crt");
            field<QLineEdit>(d, "shopfloorKeyFile")->setText("/etc/cutcell/cell.key");
            field<QDoubleSpinBox>(d, "shopfloorAxisRate")->setValue(2.5);
            field<QSpinBox>(d, "shopfloorCapacity")->setValue(500);
            field<QSpinBox>(d, "shopfloorKeepalive")->setValue(60);
            field<QPushButton>(d, "shopfloorSettingsSave")->click();
            QVERIFY2(!field<QLabel>(d, "shopfloorSettingsProblem")->isVisibleTo(&d),
                     qPrintable(field<QLabel>(d, "shopfloorSettingsProblem")->text()));
            QCOMPARE(restarts, 1);
            QVERIFY(field<QLabel>(d, "shopfloorSettingsResult")
                        ->text()
                        .contains("shop floor: restarted"));
            const cutcell::shopfloor::ShopfloorConfig back =
                cutcell::shopfloor::loadShopfloorConfig(path);
            QCOMPARE(cutcell::shopfloor::writeShopfloorConfig(back),
                     cutcell::shopfloor::writeShopfloorConfig(d.edited()));
            QCOMPARE(cutcell::readTextFile(path), cutcell::shopfloor::writeShopfloorConfig(back));
            QCOMPARE(back.axis_rate_hz, 2.5);
            QCOMPARE(back.tls.key_file, std::string("/etc/cutcell/cell.key"));
            QCOMPARE(filesIn(dir.path()), std::vector<std::string>{"shopfloor.json"});
        }
        QCOMPARE(sink.events.size(), size_t{13}); // every key differs from the defaults
        std::vector<std::string> keys;
        for (const cutcell::AuditEvent& e : sink.events) {
            QCOMPARE(e.event, std::string(cutcell::app::kShopfloorSettingChanged));
            QCOMPARE(e.actor, std::string("tester"));
            QCOMPARE(e.detail, path);
            QVERIFY(std::find(keys.begin(), keys.end(), e.key) == keys.end());
            keys.push_back(e.key);
            if (e.key == "port") {
                QCOMPARE(e.old_value, std::string("8883"));
                QCOMPARE(e.new_value, std::string("8884"));
            }
            if (e.key == "axis_rate_hz") {
                QCOMPARE(e.old_value, std::string("10"));
                QCOMPARE(e.new_value, std::string("2.5"));
                QCOMPARE(e.unit, std::string("Hz"));
            }
        }
        sink.events.clear();
        {
            ShopfloorSettingsDialog d(path, &access, restart);
            QCOMPARE(field<QLineEdit>(d, "shopfloorHost")->text(), QString("broker.shop.lan"));
            QCOMPARE(field<QDoubleSpinBox>(d, "shopfloorAxisRate")->value(), 2.5);
            field<QSpinBox>(d, "shopfloorKeepalive")->setValue(90);
            QVERIFY(d.save());
        }
        QCOMPARE(sink.events.size(), size_t{1});
        QCOMPARE(sink.events[0].key, std::string("keepalive_s"));
        QCOMPARE(sink.events[0].old_value, std::string("60"));
        QCOMPARE(sink.events[0].new_value, std::string("90"));
        QCOMPARE(sink.events[0].unit, std::string("s"));
        QCOMPARE(cutcell::shopfloor::loadShopfloorConfig(path).keepalive_s, 90);
        QLocale::setDefault(before);
    }

    // Without users anyone may; with the link off ("--shopfloor off") the dialog edits the
    // default file (its folder made) and the link stays off.
    void offStillEditsTheDefaultFile() {
        QVERIFY(!cutcell::app::stationAccess());
        cutcell::app::openShopfloor("off");
        const std::string expected = config_.filePath("cutcell/shopfloor.json").toStdString();
        QCOMPARE(cutcell::app::shopfloorSettingsPath(), expected);
        MainWindow w(nullptr);
        cutcell::app::attachShopfloor(w);
        auto* button = w.findChild<QPushButton*>("jobQueueLinkSettings");
        QVERIFY(button);
        QVERIFY(button->isEnabled());
        button->click();
        auto* d = w.findChild<ShopfloorSettingsDialog*>();
        QVERIFY(d);
        QCOMPARE(d->path(), expected);
        field<QLineEdit>(*d, "shopfloorGroupId")->setText("cutting");
        field<QLineEdit>(*d, "shopfloorEdgeNodeId")->setText("cell-07");
        QVERIFY(d->save());
        QVERIFY(std::filesystem::exists(expected));
        QVERIFY2(field<QLabel>(*d, "shopfloorSettingsResult")->text().contains("--shopfloor off"),
                 qPrintable(field<QLabel>(*d, "shopfloorSettingsResult")->text()));
        d->close();
    }

    // With users: "Link settings…" is disabled (with the reason) logged out and for an
    // operator, enabled for an engineer; it edits the file the station was given; the save is
    // in the trail under the engineer's name, one event per changed key; a log-out closes it.
    void theLinkSettingsNeedTheEngineer() {
        QTemporaryDir dir;
        const std::string db = dir.filePath("production.db").toStdString();
        {
            cutcell::AuditTrail trail(db);
            cutcell::UserDirectory users(db, trail);
            QVERIFY(users.addUser("ada", UserLevel::Administrator, "ada-pass-1", "test").ok());
            QVERIFY(users.addUser("olga", UserLevel::Operator, "olga-pass-1", "test").ok());
            QVERIFY(users.addUser("eve", UserLevel::Engineer, "eve-pass-1", "test").ok());
        }
        qInfo("%s", cutcell::app::openStationAccess(db).c_str());
        AccessControl& access = *cutcell::app::stationAccess();
        const std::string path = dir.filePath("cell.json").toStdString();
        qInfo("%s", cutcell::app::openShopfloor(path).c_str()); // no file yet: not connected
        MainWindow w(nullptr);
        cutcell::app::attachShopfloor(w);
        auto* button = w.findChild<QPushButton*>("jobQueueLinkSettings");
        QVERIFY(button);
        QVERIFY(!button->isEnabled());
        QVERIFY2(button->toolTip().contains("engineer"), qPrintable(button->toolTip()));
        QVERIFY(access.logIn("olga", "olga-pass-1").ok());
        QVERIFY(!button->isEnabled());
        QVERIFY2(button->toolTip().contains("olga"), qPrintable(button->toolTip()));
        button->click();
        QVERIFY(!w.findChild<ShopfloorSettingsDialog*>());
        QVERIFY(access.logIn("eve", "eve-pass-1").ok());
        QVERIFY(button->isEnabled());
        button->click();
        auto* d = w.findChild<ShopfloorSettingsDialog*>();
        QVERIFY(d);
        QCOMPARE(d->path(), path);
        field<QLineEdit>(*d, "shopfloorHost")->setText("broker.lan");
        field<QLineEdit>(*d, "shopfloorGroupId")->setText("cutting");
        field<QLineEdit>(*d, "shopfloorEdgeNodeId")->setText("cell-07");
        field<QPushButton>(*d, "shopfloorSettingsSave")->click();
        const QString line = field<QLabel>(*d, "shopfloorSettingsResult")->text();
        QVERIFY2(line.contains("\"enabled\": false"), qPrintable(line)); // the restarted link
        QVERIFY(w.findChild<QLabel*>("jobQueueLink")->text().contains("\"enabled\": false"));
        cutcell::AuditTrail trail(db);
        std::vector<std::string> keys;
        for (const auto& e : trail.events())
            if (e.event.event == cutcell::app::kShopfloorSettingChanged) {
                QCOMPARE(e.event.actor, std::string("eve"));
                keys.push_back(e.event.key);
            }
        QCOMPARE(keys, (std::vector<std::string>{"host", "group_id", "edge_node_id"}));
        access.logOut();
        QVERIFY(!button->isEnabled());
        QTRY_VERIFY(!w.findChild<ShopfloorSettingsDialog*>()); // closed, unsaved
    }
};

QTEST_MAIN(TestShopfloorStation)
#include "test_shopfloor_station.moc"
