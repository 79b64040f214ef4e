// Parameter forms: a bad value marks its field (red, tooltip naming key, value, unit and
// limit), counts in its tab title and disables Start with the reason; fixing it clears all.
#include "core/job/default_job.h"
#include "core/job/drive_fields.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "ui/forms/issue_text.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/main_window.h"
#include "ui/panels/control_panel.h"
#include "ui/run_controller.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QtTest>

using CutCell::ui::MainWindow;

class TestJobForms : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void everyValidatedKeyHasAField() {
        // Break the job in many ways at once: every key validateJob reports must be shown.
        MainWindow w(nullptr);
        auto job = cutcell::defaultJob();
        job.main_pipe.wall_mm = -1;
        job.branch_pipe.radius_mm = 500;
        job.cut.speed_mm_s = 900;
        cutcell::pipeRobotSpec(job).dh[3].min_deg = 100;
        cutcell::pipeRobotSpec(job).controller[2].tau_f = 0;
        cutcell::pipeRobotSpec(job).plant[4].inertia_kg_m2 = 0;
        job.sim.period_s = 1;
        job.devices.node_ids[2] = 1;
        job.engine.home_speed_deg_s = 0;
        w.editor()->setJob(job);
        QVERIFY(!w.editor()->issues().empty());
        for (const auto& issue : w.editor()->issues()) {
            QWidget* f = w.parameters()->fieldFor(issue.key);
            QVERIFY2(f, issue.key.c_str());
            QVERIFY2(f->property("invalid").toBool(), issue.key.c_str());
            // The issue as the form says it: the field's label instead of the key (defect 14).
            QVERIFY2(f->toolTip().contains(CutCell::ui::issueText(issue, f->accessibleName())),
                     qPrintable(f->toolTip()));
        }
    }

    void badValueMarksFieldAndBlocksStart_data() {
        QTest::addColumn<QString>("key");
        QTest::addColumn<double>("bad");
        QTest::addColumn<QString>("unit");
        QTest::newRow("main radius negative") << "main_pipe.radius_mm" << -5.0 << "mm";
        QTest::newRow("branch wider than main") << "branch_pipe.radius_mm" << 80.0 << "mm";
        QTest::newRow("angle above 90") << "angle_deg" << 120.0 << "deg";
        QTest::newRow("speed above limit") << "cut.speed_mm_s" << 600.0 << "mm/s";
        QTest::newRow("bevel above 60") << "cut.bevel_deg" << 75.0 << "deg";
        QTest::newRow("joint limit past 360") << "robot.dh[2].max_deg" << 400.0 << "deg";
        QTest::newRow("tau_f zero") << "controller[1].tau_f_s" << 0.0 << "s";
        QTest::newRow("period too long") << "sim.period_s" << 0.5 << "s";
        QTest::newRow("heartbeat too short") << "devices.heartbeat_timeout_ms" << 1.0 << "ms";
    }

    void badValueMarksFieldAndBlocksStart() {
        QFETCH(QString, key);
        QFETCH(double, bad);
        QFETCH(QString, unit);
        MainWindow w(nullptr);
        auto* field = qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor(key.toStdString()));
        QVERIFY(field);
        QVERIFY(!field->property("invalid").toBool());
        const double good = field->value();

        field->setValue(bad); // as typed by the operator: no clamping
        QCOMPARE(field->value(), bad);
        QVERIFY(field->property("invalid").toBool());
        // Named by its label where it has one (a table's cells have none: the key).
        const QString name = field->accessibleName().isEmpty() ? key : field->accessibleName();
        QVERIFY2(field->toolTip().contains(name), qPrintable(field->toolTip()));
        if (name != key) QVERIFY2(!field->toolTip().contains(key), qPrintable(field->toolTip()));
        QVERIFY2(field->toolTip().contains(unit), qPrintable(field->toolTip()));
        auto* start = w.controls()->startButton();
        QVERIFY(!start->isEnabled());
        QVERIFY(w.controls()->startBlockedReason().contains("invalid"));
        // The Start reason names the field as the form does (issue 21, defect 14), not the key.
        const QString reason = w.controls()->startBlockedReason();
        QVERIFY2(reason.contains(name), qPrintable(reason));
        if (name != key) QVERIFY2(!reason.contains(key), qPrintable(reason));
        // The tab holding the field counts it.
        const QString tabs = [&] {
            QStringList t;
            for (int i = 0; i < w.parameters()->tabs()->count(); ++i)
                t << w.parameters()->tabs()->tabText(i);
            return t.join('|');
        }();
        QVERIFY2(tabs.contains("(1)") || tabs.contains("(2)"), qPrintable(tabs));

        field->setValue(good);
        QVERIFY(!field->property("invalid").toBool());
        QVERIFY(w.editor()->valid());
        QVERIFY(!w.controls()->startBlockedReason().contains("invalid"));
    }

    void typedTextIsValidatedLive() {
        MainWindow w(nullptr);
        w.show();
        auto* field = qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("cut.speed_mm_s"));
        QVERIFY(field);
        w.parameters()->revealField("cut.speed_mm_s");
        field->selectAll();
        QTest::keyClicks(field, "750");
        QCOMPARE(w.editor()->job().cut.speed_mm_s, 750.0);
        QVERIFY(field->property("invalid").toBool());
        // The tooltip names the value, the limit and the unit ("... = 750 mm/s is outside
        // [0.1, 500] mm/s").
        QVERIFY2(field->toolTip().contains("750 mm/s") && field->toolTip().contains("500] mm/s"),
                 qPrintable(field->toolTip()));
    }

    // The robot's tables are drawn from their row tables (core/job/row_table.h): a column per
    // key with "label [unit]" as its header and its range as the header's tip, a field per cell
    // under the key with its row and the table's decimals.
    void robotTablesFollowTheirRowTables() {
        MainWindow w(nullptr);
        const struct {
            const char* table;
            const char* array;
            std::vector<std::pair<std::string, int>> keys; // key, decimals
            std::vector<QString> headers;
        } tables[] = {
            {"dhTable",
             "robot.dh",
             {{"alpha_deg", 1},
              {"a_mm", 1},
              {"d_mm", 1},
              {"theta_offset_deg", 1},
              {"min_deg", 1},
              {"max_deg", 1}},
             {"alpha\n[deg]", "a\n[mm]", "d\n[mm]", "offset\n[deg]", "min\n[deg]", "max\n[deg]"}},
            {"pidTable",
             "controller",
             {{"kp_nm_per_rad", 2}, {"ki_nm_per_rad_s", 1}, {"kd_nm_s_per_rad", 3}, {"tau_f_s", 4}},
             {"Kp\n[N m/rad]", "Ki\n[N m/(rad s)]", "Kd\n[N m s/rad]", "tau_f\n[s]"}},
            {"plantTable",
             "plant",
             {{"inertia_kg_m2", 4}, {"viscous_nm_s_per_rad", 3}, {"torque_limit_nm", 2}},
             {QString::fromUtf8("Inertia\n[kg m²]"), "Viscous\n[N m s/rad]",
              "Torque limit\n[N m]"}},
        };
        for (const auto& t : tables) {
            auto* table = w.findChild<QTableWidget*>(t.table);
            QVERIFY2(table, t.table);
            QCOMPARE(table->columnCount(), static_cast<int>(t.keys.size()));
            QCOMPARE(table->rowCount(), cutcell::kAxisCount);
            for (int c = 0; c < table->columnCount(); ++c) {
                QCOMPARE(table->horizontalHeaderItem(c)->text(), t.headers[static_cast<size_t>(c)]);
                QVERIFY2(table->horizontalHeaderItem(c)->toolTip().startsWith("Range "),
                         qPrintable(table->horizontalHeaderItem(c)->toolTip()));
                for (int r = 0; r < table->rowCount(); ++r) {
                    const auto& [key, decimals] = t.keys[static_cast<size_t>(c)];
                    const std::string k =
                        std::string(t.array) + "[" + std::to_string(r) + "]." + key;
                    auto* cell = qobject_cast<QDoubleSpinBox*>(table->cellWidget(r, c));
                    QVERIFY2(cell, k.c_str());
                    QCOMPARE(w.parameters()->fieldFor(k), cell);
                    QCOMPARE(cell->decimals(), decimals);
                }
            }
        }
        auto* dh = w.findChild<QTableWidget*>("dhTable");
        QCOMPARE(dh->horizontalHeaderItem(1)->toolTip(), QString("Range -5000 to 5000 mm"));
        auto* pid = w.findChild<QTableWidget*>("pidTable");
        QCOMPARE(pid->horizontalHeaderItem(3)->toolTip(), QString("Range 1e-05 to 1 s"));
        // The key of each cell edits that row of the job.
        qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("plant[5].viscous_nm_s_per_rad"))
            ->setValue(0.125);
        QCOMPARE(cutcell::pipeRobotSpec(w.editor()->job()).plant[5].viscous_nm_s_per_rad, 0.125);
        qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("robot.dh[4].theta_offset_deg"))
            ->setValue(7.5);
        QCOMPARE(cutcell::pipeRobotSpec(w.editor()->job()).dh[4].theta_offset_deg, 7.5);
    }

    void duplicateNodeIdMarksTheIdFields() {
        MainWindow w(nullptr);
        auto* id = qobject_cast<QSpinBox*>(w.parameters()->fieldFor("devices.node_ids[3]"));
        QVERIFY(id);
        id->setValue(1); // axis 0 has node 1 already
        QVERIFY(id->property("invalid").toBool());
        QVERIFY(id->toolTip().contains("used twice"));
    }

    void choiceFieldsWriteTheJob() {
        MainWindow w(nullptr);
        auto* method = qobject_cast<QComboBox*>(w.parameters()->fieldFor("method"));
        QVERIFY(method);
        method->setCurrentIndex(1);
        QCOMPARE(cutcell::pipeRobotSpec(w.editor()->job()).method, cutcell::CutMethod::StaticPipe);
        auto* target = qobject_cast<QComboBox*>(w.parameters()->fieldFor("cut.target"));
        target->setCurrentIndex(1);
        QCOMPARE(w.editor()->job().cut.target, cutcell::CutTarget::Branch);
    }

    void unreachablePathBlocksStartWithTheProblem() {
        MainWindow w(nullptr);
        auto job = cutcell::defaultJob();
        cutcell::pipeRobotSpec(job).dh[0].d_mm =
            2000; // pipe far out of the arm's reach: valid values, no path
        w.editor()->setJob(job);
        QVERIFY(w.editor()->valid());
        QTRY_VERIFY_WITH_TIMEOUT(w.run()->plan() != nullptr, 60000);
        QVERIFY(!w.run()->plan()->ok());
        QVERIFY(!w.controls()->startButton()->isEnabled());
        QVERIFY2(w.controls()->startBlockedReason().contains("not reachable"),
                 qPrintable(w.controls()->startBlockedReason()));
        QVERIFY(w.controls()->startBlockedReason().contains(
            QString::fromStdString(w.run()->plan()->outcome.message)));
    }
};

QTEST_MAIN(TestJobForms)
#include "test_job_forms.moc"
