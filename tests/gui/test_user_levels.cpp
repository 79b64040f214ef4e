// Issue 25's user levels at the operator station, against a real production record with four
// users (one per level): every machine's shipped job shows exactly the fields each level may
// change (nested levels; named examples from the issue: a setter changes speeds and bevel, not
// gains, the DH table, the E-STOP category or the devices); an operator cannot change a gain
// by the form, by typing into it, or by a programmatic setValue; nothing is editable and Start
// is blocked while logged out, yet E-STOP works; a wrong password is refused in the panel and
// five lock the user out; an idle station logs its user out; the audit trail holds the
// log-ins, the setter's change with old and new value, the refused ones not at all, and the
// E-STOP. Single-user mode (no users) leaves every field editable.
#include "sim_rig.h"
#include "station_access.h"

#include "core/job/job_io.h"
#include "core/machine/machine_module.h"
#include "core/machine/machine_registry.h"
#include "core/machine/parameter_level.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "devices/record/audit_trail.h"
#include "devices/record/user_directory.h"
#include "main_window_run.h"
#include "ui/access_control.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/job_form.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/main_window.h"
#include "ui/panels/control_panel.h"
#include "ui/panels/login_panel.h"
#include "ui/run_controller.h"

#include <QAbstractSpinBox>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>

#include <map>
#include <set>

using cutcell::UserLevel;
using CutCell::ui::AccessControl;
using CutCell::ui::MainWindow;

namespace {

// Whether the operator can change this field by hand: a text field not read-only, a check box
// or a choice that takes the mouse.
bool editableByHand(const QWidget* w) {
    if (const auto* spin = qobject_cast<const QAbstractSpinBox*>(w)) return !spin->isReadOnly();
    if (const auto* line = qobject_cast<const QLineEdit*>(w)) return !line->isReadOnly();
    if (const auto* text = qobject_cast<const QPlainTextEdit*>(w)) return !text->isReadOnly();
    return !w->testAttribute(Qt::WA_TransparentForMouseEvents);
}

// Every field of the job's machine's pages and the common pages: key -> editable by hand.
std::map<std::string, bool> fieldsOf(const MainWindow& w) {
    std::map<std::string, bool> out;
    for (const auto* form : w.parameters()->findChildren<CutCell::ui::JobForm*>())
        for (const std::string& key : form->keys())
            if (QWidget* f = w.parameters()->fieldFor(key); f && f->isEnabled())
                out[key] = editableByHand(f);
    return out;
}

std::set<std::string> editable(const std::map<std::string, bool>& fields) {
    std::set<std::string> out;
    for (const auto& [k, e] : fields)
        if (e) out.insert(k);
    return out;
}

bool hasEvent(const cutcell::AuditTrail& trail, const std::string& event, const std::string& key,
              const std::string& actor = {}) {
    for (const auto& e : trail.events())
        if (e.event.event == event && e.event.key == key &&
            (actor.empty() || e.event.actor == actor))
            return true;
    return false;
}

} // namespace

class TestUserLevels : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    std::string db_;
    const std::map<UserLevel, QString> users_ = {{UserLevel::Operator, "olga"},
                                                 {UserLevel::Setter, "sam"},
                                                 {UserLevel::Engineer, "eve"},
                                                 {UserLevel::Administrator, "ada"}};

    AccessControl& access() { return *cutcell::app::stationAccess(); }
    void logIn(UserLevel level) {
        const cutcell::Outcome o = access().logIn(users_.at(level), users_.at(level) + "-pass-1");
        QVERIFY2(o.ok(), o.message.c_str());
    }

  private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        db_ = dir_.filePath("production.db").toStdString();
        cutcell::AuditTrail trail(db_);
        cutcell::UserDirectory users(db_, trail);
        for (const UserLevel l : {UserLevel::Administrator, UserLevel::Engineer, UserLevel::Setter,
                                  UserLevel::Operator})
            QVERIFY(users
                        .addUser(users_.at(l).toStdString(), l,
                                 (users_.at(l) + "-pass-1").toStdString(), "test")
                        .ok());
        qInfo("%s", cutcell::app::openStationAccess(db_).c_str());
    }
    void init() { access().logOut(); }

    // Each machine's shipped job: logged out and as an operator nothing is editable; each
    // level's fields include the one below's; the engineer and the administrator edit all; the
    // setter edits exactly the keys core gives the setter level.
    void eachLevelSeesExactlyItsEditableFields() {
        for (const cutcell::MachineModule* m : cutcell::machines()) {
            MainWindow w(nullptr);
            QVERIFY(w.newJob(m->id())); // before the levels: a new job needs an engineer
            cutcell::app::attachStationAccess(w);
            const auto loggedOut = fieldsOf(w);
            QVERIFY2(loggedOut.size() > 5, m->id().c_str());
            QVERIFY2(editable(loggedOut).empty(), m->id().c_str());
            std::set<std::string> below;
            for (const UserLevel l : {UserLevel::Operator, UserLevel::Setter, UserLevel::Engineer,
                                      UserLevel::Administrator}) {
                logIn(l);
                const auto fields = fieldsOf(w);
                const std::set<std::string> mine = editable(fields);
                for (const std::string& k : below)
                    QVERIFY2(mine.count(k), qPrintable(QString::fromStdString(m->id() + ": " + k)));
                for (const auto& [k, e] : fields) {
                    const bool allowed =
                        l != UserLevel::Operator && cutcell::levelToChange(k, m) <= l;
                    QVERIFY2(e == allowed, qPrintable(QString("%1 as %2: %3 editable %4")
                                                          .arg(m->id().c_str(),
                                                               cutcell::userLevelName(l), k.c_str())
                                                          .arg(e)));
                }
                if (l >= UserLevel::Engineer) QCOMPARE(mine.size(), fields.size());
                below = mine;
                access().logOut();
            }
            qInfo("%s: %zu fields", m->id().c_str(), loggedOut.size());
        }
    }

    // The issue's own examples on the robot's job: a setter changes speeds and bevel, not the
    // gains, the DH table, the E-STOP category or the devices.
    void aSetterChangesSpeedsAndBevelButNoMachineParameter() {
        MainWindow w(nullptr);
        cutcell::app::attachStationAccess(w);
        logIn(UserLevel::Setter);
        const auto f = fieldsOf(w);
        QVERIFY(f.at("cut.speed_mm_s"));
        QVERIFY(f.at("cut.bevel_deg"));
        QVERIFY(!f.at("controller[0].kp_nm_per_rad"));
        QVERIFY(!f.at("robot.dh[1].a_mm"));
        QVERIFY(!f.at("engine.estop_category"));
        QVERIFY(!f.at("devices.heartbeat_timeout_ms"));
        // The tooltip names the level the field needs.
        QVERIFY2(
            w.parameters()->fieldFor("controller[0].kp_nm_per_rad")->toolTip().contains("engineer"),
            qPrintable(w.parameters()->fieldFor("controller[0].kp_nm_per_rad")->toolTip()));
    }

    // By typing into the field, by a programmatic setValue (a path around the read-only flag)
    // and through the editor: the gain stays, and the trail records no change of it.
    void anOperatorCannotChangeAGainByAnyPath() {
        MainWindow w(nullptr);
        cutcell::app::attachStationAccess(w);
        logIn(UserLevel::Operator);
        const std::string key = "controller[0].kp_nm_per_rad";
        auto* gain = qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor(key));
        QVERIFY(gain);
        const double before = cutcell::pipeRobotSpec(w.editor()->job()).controller[0].kp;
        w.show();
        w.parameters()->revealField(key);
        gain->setFocus();
        QTest::keyClick(gain, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(gain, "1234");
        QTest::keyClick(gain, Qt::Key_Return);
        QCOMPARE(cutcell::pipeRobotSpec(w.editor()->job()).controller[0].kp, before);
        QSignalSpy refused(w.editor(), &CutCell::ui::JobEditor::editRefused);
        gain->setValue(before + 100);
        QCOMPARE(refused.count(), 1);
        QCOMPARE(cutcell::pipeRobotSpec(w.editor()->job()).controller[0].kp, before);
        QTRY_COMPARE(gain->value(), before); // the field shows the job again
        cutcell::AuditTrail trail(db_);
        QVERIFY(!hasEvent(trail, cutcell::audit_event::kParameterChanged, key));
    }

    void loggedOutStartIsBlockedAndEStopWorks() {
        MainWindow w(&cutcell::app::makeRig);
        cutcell::app::attachStationAccess(w);
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->program() != nullptr, 60000);
        QVERIFY2(w.run()->startBlockedReason().contains("log in"),
                 qPrintable(w.run()->startBlockedReason()));
        w.show();
        QTest::mouseClick(w.controls()->eStopButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(state(w), cutcell::EngineState::EmergencyStop, 5000);
        // The E-STOP keeps its own words in the Start reason; the log-in comes after it.
        QTRY_VERIFY2(w.run()->startBlockedReason().contains("EMERGENCY STOP"),
                     qPrintable(w.run()->startBlockedReason()));
        cutcell::AuditTrail trail(db_);
        QVERIFY(hasEvent(trail, cutcell::audit_event::kEmergencyStop, "", "(not logged in)"));
        logIn(UserLevel::Operator);
        QVERIFY(!w.run()->startBlockedReason().contains("log in"));
    }

    // An unattended run (`cutcell --run`) asks the same gate as Start: logged out it is refused
    // before the drives are enabled, and an operator's log-in lets it run.
    void anUnattendedRunAsksTheLogInToo() {
        MainWindow w(&cutcell::app::makeRig);
        cutcell::app::attachStationAccess(w);
        w.run()->setClockMode(cutcell::ClockMode::AsFastAsPossible);
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->program() != nullptr, 60000);
        QSignalSpy finished(w.run(), &CutCell::ui::RunController::autoRunFinished);
        w.run()->startAutoRun();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 10000);
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QVERIFY2(finished.at(0).at(1).toString().contains("log in"),
                 qPrintable(finished.at(0).at(1).toString()));
        QCOMPARE(state(w), cutcell::EngineState::Idle); // not even enabled
        logIn(UserLevel::Operator);
        w.run()->startAutoRun();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 120000);
        QVERIFY2(finished.at(1).at(0).toBool(), qPrintable(finished.at(1).at(1).toString()));
    }

    // The setter's change goes to the trail with key, old and new value and the user.
    void aSettersChangeIsInTheTrail() {
        MainWindow w(nullptr);
        cutcell::app::attachStationAccess(w);
        logIn(UserLevel::Setter);
        auto* speed = qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("cut.speed_mm_s"));
        QVERIFY(speed);
        const double before = speed->value();
        // Typed digit by digit, one change: the first old value to the last new one.
        speed->setValue(before + 10);
        speed->setValue(before + 1);
        cutcell::AuditTrail trail(db_);
        const auto changes = [&] {
            std::vector<cutcell::AuditEvent> out;
            for (const auto& e : trail.events())
                if (e.event.event == cutcell::audit_event::kParameterChanged &&
                    e.event.key == "cut.speed_mm_s" && e.event.actor == "sam")
                    out.push_back(e.event);
            return out;
        };
        QTRY_COMPARE_WITH_TIMEOUT(changes().size(), size_t{1}, 5000);
        QCOMPARE(changes()[0].old_value, QString::number(before, 'g', 12).toStdString());
        QCOMPARE(changes()[0].new_value, QString::number(before + 1, 'g', 12).toStdString());
        QVERIFY(hasEvent(trail, cutcell::audit_event::kLogin, "sam"));
    }

    // The panel: a wrong password is refused with the reason, the right one logs in.
    void thePanelRefusesAWrongPasswordAndLogsInWithTheRightOne() {
        MainWindow w(nullptr);
        cutcell::app::attachStationAccess(w);
        auto* panel = w.findChild<CutCell::ui::LoginPanel*>();
        QVERIFY(panel && panel->isVisibleTo(&w));
        auto* name = panel->findChild<QLineEdit*>("loginName");
        auto* password = panel->findChild<QLineEdit*>("loginPassword");
        auto* button = panel->findChild<QPushButton*>("loginButton");
        auto* message = panel->findChild<QLabel*>("loginMessage");
        w.show();
        name->setText("eve");
        password->setText("not it at all");
        QTest::mouseClick(button, Qt::LeftButton);
        QVERIFY(password->text().isEmpty()); // at once, before the check (off the GUI thread)
        QTRY_VERIFY2(message->text().contains("wrong"), qPrintable(message->text()));
        QVERIFY(!access().loggedIn());
        password->setText("eve-pass-1");
        QTest::keyClick(password, Qt::Key_Return);
        QTRY_VERIFY(access().loggedIn());
        QCOMPARE(*access().level(), UserLevel::Engineer);
        QVERIFY(panel->findChild<QLabel*>("loginUser")->text().contains("eve"));
    }

    void anIdleStationLogsItsUserOut() {
        access().setIdleTimeoutS(1);
        logIn(UserLevel::Engineer);
        QTRY_VERIFY_WITH_TIMEOUT(!access().loggedIn(), 3000);
        access().setIdleTimeoutS(600);
        cutcell::AuditTrail trail(db_);
        bool idle = false;
        for (const auto& e : trail.events())
            idle = idle || (e.event.event == cutcell::audit_event::kLogout &&
                            e.event.detail == "idle for 1 s");
        QVERIFY(idle);
    }

    // A job file with a changed gain needs the engineer level to be opened (the job stays);
    // one that changes only process parameters opens for an operator; so does the gain for an
    // engineer. File -> New (another machine's defaults) needs an engineer too.
    void openingAFileThatChangesAGainNeedsAnEngineer() {
        MainWindow w(nullptr);
        w.setErrorPrompt([](const QString&, const QString&) {});
        cutcell::app::attachStationAccess(w);
        const cutcell::Job original = w.editor()->job();
        cutcell::Job gain = original, speed = original;
        cutcell::pipeRobotSpec(gain).controller[0].kp += 100;
        speed.cut.speed_mm_s += 1;
        const QString gainFile = dir_.filePath("gain.json"),
                      speedFile = dir_.filePath("speed.json");
        cutcell::saveJobFile(gain, gainFile.toStdString());
        cutcell::saveJobFile(speed, speedFile.toStdString());
        logIn(UserLevel::Operator);
        QString why;
        QVERIFY(!w.openJob(gainFile, &why));
        QVERIFY2(why.contains("controller[0].kp_nm_per_rad") && why.contains("engineer"),
                 qPrintable(why));
        QCOMPARE(cutcell::pipeRobotSpec(w.editor()->job()).controller[0].kp,
                 cutcell::pipeRobotSpec(original).controller[0].kp);
        QVERIFY2(w.openJob(speedFile, &why), qPrintable(why));
        QVERIFY(!w.newJob(cutcell::machines().back()->id()));
        access().logOut();
        logIn(UserLevel::Engineer);
        QVERIFY2(w.openJob(gainFile, &why), qPrintable(why));
        QCOMPARE(cutcell::pipeRobotSpec(w.editor()->job()).controller[0].kp,
                 cutcell::pipeRobotSpec(original).controller[0].kp + 100);
    }

    // An administrator demotes or removes a user who is logged in (the CLI beside the
    // station): the station takes the new level at its next look at the list, or logs out.
    void aLevelChangedMeanwhileTakesEffectAtTheStation() {
        MainWindow w(nullptr);
        cutcell::app::attachStationAccess(w);
        logIn(UserLevel::Engineer);
        QVERIFY(fieldsOf(w).at("controller[0].kp_nm_per_rad"));
        cutcell::AuditTrail trail(db_);
        cutcell::UserDirectory users(db_, trail);
        QVERIFY(users.setLevel("eve", UserLevel::Setter, "ada").ok());
        access().refreshUsers(); // what its 5 s timer does
        QCOMPARE(*access().level(), UserLevel::Setter);
        QVERIFY(!fieldsOf(w).at("controller[0].kp_nm_per_rad"));
        QVERIFY(users.setLevel("eve", UserLevel::Engineer, "ada").ok());
        QVERIFY(users.addUser("tmp", UserLevel::Operator, "tmp-pass-1", "ada").ok());
        QVERIFY(access().logIn("tmp", "tmp-pass-1").ok());
        QVERIFY(users.removeUser("tmp", "ada").ok());
        access().refreshUsers();
        QVERIFY(!access().loggedIn());
    }

    // A user list that cannot be opened (here: the record's path is a folder) locks every
    // field and Start; it never opens them.
    void anUnreadableUserListLocksEverything() {
        qInfo("%s", cutcell::app::openStationAccess(dir_.path().toStdString()).c_str());
        {
            MainWindow w(nullptr);
            cutcell::app::attachStationAccess(w);
            const auto f = fieldsOf(w);
            QVERIFY(!f.empty());
            QVERIFY(editable(f).empty());
            QVERIFY2(w.run()->startBlockedReason().contains("cannot be read"),
                     qPrintable(w.run()->startBlockedReason()));
        }
        cutcell::app::openStationAccess(db_);
    }

    // Last: with the record off the station is single-user - every field editable, no panel.
    void singleUserModeEditsEverything() {
        cutcell::app::openStationAccess("off");
        MainWindow w(nullptr);
        cutcell::app::attachStationAccess(w);
        const auto f = fieldsOf(w);
        QCOMPARE(editable(f).size(), f.size());
        QVERIFY(!w.findChild<CutCell::ui::LoginPanel*>()->isVisibleTo(&w));
        QVERIFY(w.run()->startBlockedReason().isEmpty() ||
                !w.run()->startBlockedReason().contains("log in"));
    }
};

QTEST_MAIN(TestUserLevels)
#include "test_user_levels.moc"
