// A sixth machine from the test tree alone (issue 20): a one-axis rotary table - its core module
// (field table, plan into a joint spline), its operator-station module (a form page built from
// the same table) - registered with one call per layer, then planned, run in the motion engine
// on a simulated drive to Completed, and edited in the GUI's forms: its page and no Pipes tab, a
// value beyond its range named with key, value, unit and limit, the job written and read back.
// Nothing outside this file knows the machine.
#include "core/engine/motion_engine.h"
#include "core/job/default_job.h"
#include "core/job/field_table.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "core/sim/tracking_stats.h"
#include "devices/sim/simulated_drive.h"
#include "ui/forms/job_editor.h"
#include "ui/forms/job_form.h"
#include "ui/forms/parameter_tabs.h"
#include "ui/machine/machine_ui_registry.h"
#include "ui/machine/module_planned_machine_ui.h"
#include "ui/main_window.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QtTest>

#include <cmath>

namespace {

using namespace cutcell;

constexpr const char* kTableId = "rotary_table_test";

struct RotaryTableSpec : MachineSpecOf<RotaryTableSpec> {
    double turn_deg = 90;
    double time_s = 1.5;
    int points = 31;
};

using Field = SectionField<RotaryTableSpec>;
// One entry per key, kept as a table.
// clang-format off
const Field kFields[] = {
    {.key = "turn.angle_deg", .unit = "deg", .label = "Turn", .lo = -720, .hi = 720,
     .check = FieldCheck::Range, .decimals = 2,
     .number = [](RotaryTableSpec& s) -> double& { return s.turn_deg; }},
    {.key = "turn.time_s", .unit = "s", .label = "Time", .lo = 0.1, .hi = 60,
     .check = FieldCheck::Positive, .decimals = 2,
     .number = [](RotaryTableSpec& s) -> double& { return s.time_s; }},
    {.key = "turn.points", .unit = "points", .label = "Spline points", .lo = 5, .hi = 1000,
     .check = FieldCheck::Range, .integer = [](RotaryTableSpec& s) -> int& { return s.points; }},
};
// clang-format on
std::span<const Field> tableFields() {
    return kFields;
}
const RotaryTableSpec& specOf(const Job& job) {
    static const RotaryTableSpec none;
    const auto* s = job.machine_spec.as<RotaryTableSpec>();
    return s ? *s : none;
}

class RotaryTableModule : public MachineModule {
  public:
    std::string id() const override { return kTableId; }
    std::string title() const override { return "Rotary table (one axis, test machine)"; }
    std::vector<AxisInfo> axes(const Job&) const override {
        return {{"C (table)", AxisUnit::Rotary, -720, 720, CommandMode::Position}};
    }
    Job defaultJob() const override {
        const Job common = cutcell::defaultJob();
        Job job;
        job.sim = common.sim;
        job.engine = common.engine;
        job.devices = common.devices;
        job.machine = kTableId;
        job.name = "Rotary table";
        job.machine_spec.set(RotaryTableSpec{});
        return job;
    }
    void readSection(const json::Value& section, Job& job) const override {
        SectionReader m(section, "machine");
        m.get("kind");
        RotaryTableSpec s;
        readFields(m, tableFields(), s);
        m.finish();
        job.machine_spec.set(s);
    }
    json::Value writeSection(const Job& job) const override {
        json::Object out{{"kind", kTableId}};
        for (auto& member : writeFields(tableFields(), specOf(job)))
            out.push_back(std::move(member));
        return out;
    }
    void migrateSchema1(json::Object&) const override {}
    std::vector<JobIssue> validate(const Job& job) const override {
        IssueChecker c;
        checkFields(c, tableFields(), specOf(job));
        return c.issues;
    }
    Outcome canOpen() const override {
        return Outcome::refuse("the test table has no CAN drive", "devices.kind");
    }
    MachinePlan plan(const Job& job, const std::string& jobText,
                     const PlanOptions&) const override {
        const RotaryTableSpec& s = specOf(job);
        MachinePlan out;
        // A smooth-step turn: at rest at both ends.
        std::vector<JointVector> knots;
        for (int k = 0; k < s.points; ++k) {
            const double u = k / double(s.points - 1);
            JointVector q = JointVector::Zero();
            q[0] = deg2rad(s.turn_deg) * u * u * u * (10 - 15 * u + 6 * u * u);
            knots.push_back(q);
        }
        auto p = std::make_shared<MotionProgram>();
        p->machine = kTableId;
        p->method = "turn";
        p->axis_count = 1;
        p->axis_names[0] = "C (table)";
        p->axis_modes[0] = AxisCommandMode::Position;
        p->spline = JointSpline(knots, s.time_s / (s.points - 1));
        p->cut_time_s = s.time_s;
        p->point_count = static_cast<size_t>(s.points);
        p->min_position[0] = deg2rad(-720);
        p->max_position[0] = deg2rad(720);
        p->terms.tool = "spindle";
        p->terms.path_length = false;
        p->name = job.name;
        p->source_text = jobText;
        out.program = p;
        out.summary = "a turn of " + num(s.turn_deg) + " deg in " + num(s.time_s) + " s";
        out.outcome = Outcome::done();
        return out;
    }
    std::vector<ExportInfo> exports() const override { return {}; }
    std::string exportFile(const std::string& id, const Job&, const MachinePlan&) const override {
        throw std::invalid_argument("the rotary table has no export " + id);
    }
    json::Value runReport(const Job&, const MachinePlan&,
                          const TrackingReport& report) const override {
        return reportToJson(report);
    }
};

class RotaryTableUi : public CutCell::ui::ModulePlannedMachineUi {
    class Page : public CutCell::ui::JobForm {
      public:
        explicit Page(CutCell::ui::JobEditor* editor) : JobForm(editor) {
            auto* box = new QGroupBox(QStringLiteral("Turn"), this);
            auto* form = new QFormLayout(box);
            for (const char* key : {"turn.angle_deg", "turn.time_s", "turn.points"})
                addSectionRow(form, sectionField(tableFields(), key), &spec);
            mainLayout()->addWidget(box);
        }
        static RotaryTableSpec& spec(Job& j) {
            if (!j.machine_spec.as<RotaryTableSpec>()) j.machine_spec.set(RotaryTableSpec{});
            return *j.machine_spec.as<RotaryTableSpec>();
        }
    };

  public:
    std::string id() const override { return kTableId; }
    QString title() const override { return QStringLiteral("Rotary table (test)"); }
    std::vector<CutCell::ui::FormPage> formPages() const override {
        return {{QStringLiteral("Table"),
                 [](CutCell::ui::JobEditor* e) -> CutCell::ui::JobForm* { return new Page(e); }}};
    }
    std::vector<std::pair<std::string, QString>> unusedCommonFields() const override {
        return pipeJointFields(QStringLiteral("The table turns; it cuts no pipe joint."));
    }
    bool buildScene(const Job&, const MachinePlan&, view3d::SceneModel*,
                    QString* why) const override {
        if (why) *why = QStringLiteral("no 3D scene for the test table");
        return false;
    }
};

} // namespace

class TestSixthMachine : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        // One line per layer: the core module, the operator station's module.
        machines(); // the shipped ones first
        registerMachine(std::make_unique<RotaryTableModule>());
        CutCell::ui::registerMachineUi(std::make_unique<RotaryTableUi>());
    }

    void plansAndRunsInTheEngine() {
        const MachineModule* m = findMachine(kTableId);
        QVERIFY(m);
        Job job = m->defaultJob();
        QVERIFY(validateJob(job).empty());
        // Written and read back through the job file.
        const Job back = parseJob(json::write(jobToJson(job)));
        QCOMPARE(back.machine, std::string(kTableId));
        QCOMPARE(specOf(back).turn_deg, specOf(job).turn_deg);
        const MachinePlan plan = m->plan(job);
        QVERIFY(plan.ok());

        Job robot = cutcell::defaultJob(); // a servo's gains for the simulated drive
        SimulatedDriveConfig dc;
        dc.gains = cutcell::pipeRobotSpec(robot).controller[0];
        dc.plant = cutcell::pipeRobotSpec(robot).plant[0];
        dc.period_s = job.sim.period_s;
        SimulatedDrive drive(dc);
        EngineDevices devices;
        devices.axes[0] = &drive;
        EngineConfig config;
        config.clock = ClockMode::AsFastAsPossible;
        config.period_s = job.sim.period_s;
        config.spec = job.engine;
        config.spec.runs_dir.clear();
        MotionEngine engine(devices, config);
        engine.startThread();
        QVERIFY(engine.load(plan.program));
        QVERIFY(engine.enable());
        QTRY_VERIFY2_WITH_TIMEOUT(engine.state() == EngineState::Ready,
                                  cutcell::toString(engine.state()), 10000);
        QVERIFY(engine.home());
        // Homed and at rest again (the state alone reads Ready before the move has begun).
        bool homed = false;
        const auto drain = [&] {
            TelemetrySample t;
            while (engine.popTelemetry(t))
                homed = t.homed && t.state == EngineState::Ready;
            return homed;
        };
        QTRY_VERIFY_WITH_TIMEOUT(drain(), 10000);
        QVERIFY(engine.start());
        QTRY_VERIFY_WITH_TIMEOUT(engine.state() == EngineState::Completed ||
                                     engine.state() == EngineState::Fault ||
                                     engine.state() == EngineState::EmergencyStop,
                                 30000);
        QVERIFY2(engine.state() == EngineState::Completed, cutcell::toString(engine.state()));
        TrackingReport report;
        QVERIFY(engine.lastRunReport(report));
        QCOMPARE(report.axis_count, 1);
        QVERIFY(std::isfinite(report.maxAbs(0)) && report.maxAbs(0) < 2.0); // deg
        engine.stopThread();
    }

    void editedInTheOperatorStation() {
        CutCell::ui::MainWindow w(nullptr);
        QVERIFY(w.newJob(kTableId));
        QVERIFY(w.parameters()->tabShown("Table"));
        QVERIFY(!w.parameters()->tabShown("Pipes"));
        auto* turn = qobject_cast<QDoubleSpinBox*>(w.parameters()->fieldFor("turn.angle_deg"));
        QVERIFY(turn);
        turn->setValue(1000); // beyond 720 deg
        QTRY_VERIFY(!w.editor()->issues().empty());
        bool named = false;
        for (const auto& issue : w.editor()->issues())
            named = named || (issue.key == "turn.angle_deg" &&
                              issue.message.find("deg") != std::string::npos &&
                              issue.message.find("720") != std::string::npos);
        QVERIFY(named);
        QCOMPARE(specOf(w.editor()->job()).turn_deg, 1000.0);
    }
};

QTEST_MAIN(TestSixthMachine)
#include "test_sixth_machine.moc"
