// The robot's Controller page: the rigid-body mechanics' fields (plant model, gravity
// feed-forward, links, drives, chuck) edit the job, and "Tune (SIMC)" writes the tuned gains into
// the PID table as edits - the job holds them, the document is modified - or says why not.
#include "core/job/default_job.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "core/machines/pipe_robot/pipe_robot_tuning.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/job_document.h"
#include "ui/main_window.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QtTest>

using CutCell::ui::MainWindow;

namespace {

double cell(MainWindow& w, const std::string& key) {
    auto* box = qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor(key));
    return box ? box->value() : -1;
}

std::string gainKey(size_t axis, const char* field) {
    return cutcell::rowKey("controller", axis) + "." + field;
}

} // namespace

class TestPipeRobotTuning : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void mechanicsFieldsEditTheJob() {
        MainWindow w(nullptr);
        w.editor()->setJob(cutcell::defaultJob());
        const struct {
            const char* name;
            int rows, columns;
        } tables[] = {{"linkMassTable", cutcell::kArmJointCount, 4},
                      {"linkInertiaTable", cutcell::kArmJointCount, 3},
                      {"linkProductsTable", cutcell::kArmJointCount, 3},
                      {"driveTable", cutcell::kAxisCount, 2},
                      {"driveFrictionTable", cutcell::kAxisCount, 3}};
        for (const auto& t : tables) {
            auto* table = w.findChild<QTableWidget*>(t.name);
            QVERIFY2(table, t.name);
            QCOMPARE(table->rowCount(), t.rows);
            QCOMPARE(table->columnCount(), t.columns);
        }
        qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("robot.links[2].iyy_kg_cm2"))
            ->setValue(123.5);
        QCOMPARE(cutcell::pipeRobotSpec(w.editor()->job()).links[2].iyy_kg_cm2, 123.5);
        qobject_cast<QDoubleSpinBox*>(
            w.parameters()->fieldFor("robot.drives[4].viscous_nm_s_per_rad"))
            ->setValue(0.25);
        QCOMPARE(cutcell::pipeRobotSpec(w.editor()->job()).drives[4].viscous_nm_s_per_rad, 0.25);
        qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("robot.chuck.inertia_kg_m2"))
            ->setValue(0.05);
        QCOMPARE(cutcell::pipeRobotSpec(w.editor()->job()).chuck.inertia_kg_m2, 0.05);
        auto* model = qobject_cast<QComboBox*>(w.parameters()->fieldFor("plant_model"));
        QVERIFY(model);
        model->setCurrentIndex(1);
        QCOMPARE(cutcell::pipeRobotSpec(w.editor()->job()).plant_model,
                 cutcell::PlantModel::Linear);
        auto* gravity = qobject_cast<QCheckBox*>(w.parameters()->fieldFor("gravity_feedforward"));
        QVERIFY(gravity);
        gravity->setChecked(true);
        QVERIFY(cutcell::pipeRobotSpec(w.editor()->job()).gravity_feedforward);
    }

    void tuneWritesTheGainsIntoThePidTable() {
        MainWindow w(nullptr);
        // Gains that are not SIMC's (the default job may hold SIMC's already): the table changes.
        cutcell::Job job = cutcell::defaultJob();
        for (cutcell::PidGains& g : cutcell::pipeRobotSpec(job).controller)
            g = {1000, 20000, 10, g.tau_f};
        w.editor()->setJob(job);
        QVERIFY(!w.document()->modified());
        const cutcell::PipeRobotTuning expected = cutcell::tunePipeRobot(job);
        QVERIFY(expected.outcome.ok());
        QCOMPARE(cell(w, gainKey(2, "kp_nm_per_rad")), 1000.0);
        QVERIFY(expected.gains[2].kp != 1000.0);

        auto* button = w.findChild<QPushButton*>("tuneButton");
        auto* status = w.findChild<QLabel*>("tuneStatus");
        QVERIFY(button && status);
        button->click();
        QVERIFY(!button->isEnabled()); // tuning off the GUI thread
        QTRY_VERIFY_WITH_TIMEOUT(button->isEnabled(), 20000);
        QVERIFY2(status->text().contains("SIMC gains written"), qPrintable(status->text()));
        QVERIFY(status->toolTip().contains("gain margin"));

        for (size_t i = 0; i < cutcell::kAxisCount; ++i) {
            const cutcell::PidGains& g = cutcell::pipeRobotSpec(w.editor()->job()).controller[i];
            QCOMPARE(g.kp, expected.gains[i].kp);
            QCOMPARE(g.ki, expected.gains[i].ki);
            QCOMPARE(g.kd, expected.gains[i].kd);
            QCOMPARE(g.tau_f, cutcell::pipeRobotSpec(job).controller[i].tau_f);
            QCOMPARE(cell(w, gainKey(i, "kp_nm_per_rad")), expected.gains[i].kp);
            QCOMPARE(cell(w, gainKey(i, "ki_nm_per_rad_s")), expected.gains[i].ki);
            QCOMPARE(cell(w, gainKey(i, "kd_nm_s_per_rad")), expected.gains[i].kd);
        }
        QVERIFY(w.document()->modified());
    }

    void tuneRefusesAnInvalidJob() {
        MainWindow w(nullptr);
        cutcell::Job job = cutcell::defaultJob();
        cutcell::pipeRobotSpec(job).plant[1].inertia_kg_m2 = 0; // invalid
        w.editor()->setJob(job);
        auto* button = w.findChild<QPushButton*>("tuneButton");
        auto* status = w.findChild<QLabel*>("tuneStatus");
        button->click();
        QVERIFY(button->isEnabled());
        QVERIFY2(status->text().startsWith("Not tuned"), qPrintable(status->text()));
        QCOMPARE(cutcell::pipeRobotSpec(w.editor()->job()).controller[2].kp,
                 cutcell::pipeRobotSpec(job).controller[2].kp);
        QVERIFY(!w.document()->modified());
    }
};

QTEST_MAIN(TestPipeRobotTuning)
#include "test_pipe_robot_tuning.moc"
