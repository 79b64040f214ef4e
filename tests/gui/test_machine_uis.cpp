// The machine modules of the operator station (issue 9): File -> New asks which machine and
// creates that machine's default job with its own form pages, Export menu and plot channels;
// the robot offers no G-code; the profile cutter plots A in deg and X in mm, each on a plot of
// its unit, and no Cartesian x/y/z (its tip frame turns with the pipe).
#include "core/machines/flying_saw/flying_saw_module.h"
#include "plots/tracking_plots_widget.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/machine/machine_ui_registry.h"
#include "ui/machine_exports.h"
#include "ui/main_window.h"
#include "ui/panels/monitor_views.h"
#include "ui/run_controller.h"

#include <QAction>
#include <QMenu>
#include <QTabWidget>
#include <QtTest>

#include <set>

using CutCell::ui::ExportKind;
using CutCell::ui::MachineUi;
using CutCell::ui::MainWindow;

namespace {

const char* const kRobot = "pipe_robot_6axis";
const char* const kProfile = "profile_cutter_2axis";

// File -> New through the menu action, the machine prompt answered by `id`.
void newFromMenu(MainWindow& w, const std::string& id) {
    w.setMachinePrompt([id] { return id; });
    auto* action = w.findChild<QAction*>("actionNew");
    QVERIFY(action);
    action->trigger();
}

std::vector<ExportKind> exportMenuKinds(MainWindow& w) {
    std::vector<ExportKind> kinds;
    auto* menu = w.findChild<QMenu*>("exportMenu");
    if (!menu) return kinds;
    for (QAction* a : menu->actions())
        if (!a->isSeparator()) kinds.push_back(static_cast<ExportKind>(a->data().toInt()));
    return kinds;
}

// The plots after the plan of the job in the editor (the views adapt on planChanged).
void waitForPlan(MainWindow& w) {
    QSignalSpy planned(w.run(), &CutCell::ui::RunController::planChanged);
    w.run()->replanNow();
    QVERIFY(planned.wait(60000));
}

} // namespace

class TestMachineUis : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void registryListsBothShippedMachines() {
        std::set<std::string> ids;
        for (const MachineUi* m : CutCell::ui::machineUis()) {
            QVERIFY2(ids.insert(m->id()).second, m->id().c_str()); // unique
            QVERIFY(!m->title().isEmpty());
            QCOMPARE(CutCell::ui::findMachineUi(m->id()), m);
            // Its default job is for it and valid.
            const cutcell::Job job = m->defaultJob();
            QCOMPARE(job.machine, m->id());
        }
        QVERIFY(ids.count(kRobot) && ids.count(kProfile));
        QVERIFY(CutCell::ui::findMachineUi("no_such_machine") == nullptr);
    }

    void fileNewGivesEachMachinesPagesAndExports() {
        MainWindow w(nullptr);
        for (const MachineUi* m : CutCell::ui::machineUis()) {
            newFromMenu(w, m->id());
            QCOMPARE(w.editor()->job().machine, m->id());
            QVERIFY2(w.editor()->valid(), m->id().c_str());
            // Its pages are shown, every other machine's pages are hidden.
            std::set<QString> own;
            for (const auto& page : m->formPages()) {
                own.insert(page.title);
                QVERIFY2(w.parameters()->tabShown(page.title), qPrintable(page.title));
            }
            for (const MachineUi* other : CutCell::ui::machineUis())
                if (other != m)
                    for (const auto& page : other->formPages())
                        if (!own.count(page.title))
                            QVERIFY2(!w.parameters()->tabShown(page.title), qPrintable(page.title));
            // Every machine's job has a name; the Pipes and Cut pages only for the machines
            // that use their fields (a machine without pipes has no Pipes tab).
            QVERIFY(w.parameters()->tabShown("Job"));
            bool cutUnused = false, pipesUnused = false;
            for (const auto& [key, why] : m->unusedCommonFields()) {
                cutUnused = cutUnused || key == "cut.speed_mm_s";
                pipesUnused = pipesUnused || key == "main_pipe.radius_mm";
            }
            QCOMPARE(w.parameters()->tabShown("Pipes"), !pipesUnused);
            QCOMPARE(w.parameters()->tabShown("Cut"), !cutUnused);
            // Its exports are the Export menu's entries, in its order.
            QCOMPARE(exportMenuKinds(w), m->exports());
        }
    }

    void cancelledMachinePromptKeepsTheJob() {
        MainWindow w(nullptr);
        QVERIFY(w.newJob(kProfile));
        newFromMenu(w, std::string());
        QCOMPARE(w.editor()->job().machine, std::string(kProfile));
        QVERIFY(!w.newJob("no_such_machine"));
        QCOMPARE(w.editor()->job().machine, std::string(kProfile));
    }

    void robotOffersNoGcode() {
        MainWindow w(nullptr);
        newFromMenu(w, kRobot);
        const auto kinds = exportMenuKinds(w);
        QVERIFY(!kinds.empty()); // the templates
        QVERIFY(std::find(kinds.begin(), kinds.end(), ExportKind::Gcode) == kinds.end());
        QTemporaryDir dir;
        QString err;
        const QString ngc = dir.filePath("robot.ngc");
        QVERIFY(!CutCell::ui::exportCut(ExportKind::Gcode, w.editor()->job(), ngc, &err));
        QVERIFY2(err.contains(ngc) && err.contains("G-code"), qPrintable(err));
        QVERIFY(!QFile::exists(ngc));
        // The profile cutter does offer it.
        newFromMenu(w, kProfile);
        const auto profileKinds = exportMenuKinds(w);
        QVERIFY(std::find(profileKinds.begin(), profileKinds.end(), ExportKind::Gcode) !=
                profileKinds.end());
    }

    void profileCutterPlotsAinDegXinMmAndNoCartesianXyz() {
        MainWindow w(nullptr);
        newFromMenu(w, kProfile);
        waitForPlan(w);
        auto* plots = w.plots()->plots();
        QCOMPARE(plots->axisCount(), 2);
        QVERIFY(plots->axisNames().at(0).startsWith("A"));
        QVERIFY(plots->axisNames().at(1).startsWith("X"));
        QCOMPARE(plots->axisUnits(), QStringList({"deg", "mm"}));
        // A on the deg plot alone, X on the mm plot alone: no millimetres on a degree scale.
        const QStringList titles = plots->plotTitles();
        int degPlot = -1, mmPlot = -1;
        for (int i = 0; i < titles.size(); ++i) {
            if (titles[i].contains("(deg)")) degPlot = i;
            if (titles[i] == "error (mm)") mmPlot = i;
            const QStringList traces = plots->plotTraceNames(i);
            QVERIFY2(!(traces.contains("x") || traces.contains("y") || traces.contains("z")),
                     qPrintable(titles[i]));
        }
        QVERIFY2(degPlot >= 0 && mmPlot >= 0, qPrintable(titles.join(" | ")));
        QCOMPARE(plots->plotTraceNames(degPlot), QStringList({plots->axisNames().at(0)}));
        QCOMPARE(plots->plotTraceNames(mmPlot), QStringList({plots->axisNames().at(1)}));
    }

    // A job whose plan cannot be made (an invalid value) still names its own axes in the plots:
    // the saw's carriage and feeds, not the robot's A0..J5 (seen in a screenshot, issue 20).
    void anInvalidJobsPlotsNameItsOwnAxes() {
        MainWindow w(nullptr);
        QTemporaryDir dir;
        const QString path = dir.filePath("saw.json");
        QFile in(QStringLiteral(CUTCELL_SOURCE_DIR "/resources/jobs/flying_saw_job.json"));
        QVERIFY(in.open(QIODevice::ReadOnly));
        QByteArray text = in.readAll();
        text.replace("\"overcut_mm\": 1", "\"overcut_mm\": 15");
        text.replace("\"wall_mm\": 2", "\"wall_mm\": 29");
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(text);
        out.close();
        QString why;
        w.openJob(path, &why);
        QCOMPARE(w.editor()->job().machine, std::string(cutcell::kFlyingSawId));
        QVERIFY(w.run()->startBlockedReason().contains("invalid"));
        const QStringList names = w.plots()->plots()->axisNames();
        QVERIFY2(names.size() == 4 && names.at(0).contains("carriage"),
                 qPrintable(names.join(",")));
        QCOMPARE(w.plots()->plots()->axisUnits(), QStringList({"mm", "deg", "mm", "mm"}));
    }

    void robotPlotsSixJointsInDegAndCartesianXyz() {
        MainWindow w(nullptr);
        newFromMenu(w, kProfile); // from another machine: the channels change back
        waitForPlan(w);
        newFromMenu(w, kRobot);
        waitForPlan(w);
        auto* plots = w.plots()->plots();
        QCOMPARE(plots->axisCount(), 6);
        QCOMPARE(plots->axisUnits(), QStringList(6, "deg"));
        const QStringList titles = plots->plotTitles();
        QCOMPARE(titles.size(), 2);
        QVERIFY(titles[0].contains("(deg)"));
        QCOMPARE(plots->plotTraceNames(0), plots->axisNames());
        QCOMPARE(plots->plotTraceNames(1), QStringList({"x", "y", "z"}));
    }
};

QTEST_MAIN(TestMachineUis)
#include "test_machine_uis.moc"
