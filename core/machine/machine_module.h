#pragma once
// One seam per machine. A machine module says what the machine is (id, title, axes), reads and
// validates its own `machine` section of the job, plans a cut into the MotionProgram the
// engine runs, and offers its exports. The controller (engine, CLI, GUI) is the same for every
// machine and picks the module by the job's `machine.kind`, as LinuxCNC picks a kinematics
// module by configuration; the simulated devices of a machine are built beside the devices
// (devices/machines/, see devices/machines/rig_registry.h), as a ros2_control hardware
// interface has a mock and a real implementation behind one interface.
//
// Adding a machine: a folder core/machines/<name>/ with a class derived from MachineModule,
// one line in core/machines/register_machines.cpp, and (for `run`) one line in
// devices/machines/rig_registry.cpp. See README, "Adding a machine".
#include "core/common/outcome.h"
#include "core/common/types.h"
#include "core/devices/device_interfaces.h"
#include "core/engine/motion_program.h"
#include "core/job/job.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/job_importer.h"
#include "core/machine/plan_options.h"
#include "core/sim/line_chart.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cutcell {

struct TrackingReport;

// AxisUnit (core/common/types.h) and the CiA 402 command mode (core/devices) are the engine's.
using CommandMode = AxisCommandMode;

struct AxisInfo {
    std::string name; // "A (pipe turn)", "theta1"
    AxisUnit unit = AxisUnit::Rotary;
    double min = -180; // deg or mm
    double max = 180;
    CommandMode mode = CommandMode::Position;
};

const char* unitSymbol(AxisUnit u);         // "deg" or "mm"
const char* commandModeName(CommandMode m); // "position", "velocity", "torque"

// What plan() gives: the program for the engine and the machine's own data for its exports.
struct MachinePlan {
    // Ok; Refused when the job is valid but the machine cannot make this cut (reach, travel,
    // rates): the message is one sentence naming the point, the value, the limit, the key the
    // job key when the machine knows it; Cancelled when PlanOptions::cancel was set while
    // planning (no program). Refused until the module has planned.
    Outcome outcome = Outcome::refuse({});
    std::string summary; // one line for the operator ("530.1 mm at 8 mm/s, 66.3 s, ...")
    std::shared_ptr<const MotionProgram> program;
    std::shared_ptr<const void> data; // owned by the module that made it (its plan type)
    bool ok() const { return outcome.ok(); }
    bool cancelled() const { return outcome.cancelled(); }
};

// A file the machine can write from a plan.
struct ExportInfo {
    std::string id;           // "gcode", "path_csv", "template_svg", ...
    std::string title;        // "LinuxCNC G-code (X/A)"
    std::string default_name; // "cut.ngc"
    bool plan_file = false;   // written by `cutcell-cli plan --out DIR`
    bool binary = false;      // PDF
};

// How to write an export, beyond the job: the paper of a cutting template ("single", "A4",
// "A3"; core/pipe_joint/template_tiles.h). Exports that take none ignore it.
struct ExportSettings {
    std::string paper = "single";
    // The accepted papers, for option lists (machine_registry.cpp).
    static const std::vector<std::string>& papers();
};

// What MachineModule::compareMethods gives (`cutcell-cli compare`): the files' contents and
// the figures, each written as SVG and PNG under its file stem.
struct MethodComparisonFiles {
    std::string json;     // comparison.json: the table and the time series
    std::string markdown; // comparison.md: the table
    std::vector<std::pair<std::string, LineChart>> charts; // file stem -> figure
};

// How `cutcell-cli tune` and the forms ask a machine to tune its drives' controllers.
struct TuneOptions {
    double tau_c_s = 0; // desired closed-loop time constant; <= 0: the machine's default
    PlanOptions plan;   // progress and cancel of the plan the tuning may need
};

class MachineModule {
  public:
    virtual ~MachineModule() = default;

    virtual std::string id() const = 0;    // the job's machine.kind
    virtual std::string title() const = 0; // "Pipe-cutting robot (chuck + 5-DOF arm)"
    // The axes with their limits as the job sets them.
    virtual std::vector<AxisInfo> axes(const Job& job) const = 0;

    // A complete job for this machine (File -> New).
    virtual Job defaultJob() const = 0;
    // Reads the `machine` section (kind already checked) into job. Unknown keys are refused
    // with the nearest valid key as a hint (SectionReader). Throws JobError.
    virtual void readSection(const json::Value& section, Job& job) const = 0;
    // The `machine` section of job (with "kind" first).
    virtual json::Value writeSection(const Job& job) const = 0;
    // Schema 1 kept machine keys at the top level and tolerated keys a machine did not read:
    // given the top-level keys moved into the section, drop those this machine never read.
    virtual void migrateSchema1(json::Object& section) const = 0;
    // Range and consistency problems of the machine's part of the job (key, value, unit, limit).
    virtual std::vector<JobIssue> validate(const Job& job) const = 0;

    // Whether the machine can run on CANopen drives: Ok, or Refused with why (the key
    // devices.kind).
    virtual Outcome canOpen() const = 0;
    // The external sensors the machine reads (engine sensor k = entry k: "line encoder"); on
    // CAN each is a CiA 406 encoder node (devices.sensor_node_ids). None by default.
    virtual std::vector<std::string> sensorNames() const { return {}; }
    // How the machine's runs are told (its tool, what it counts) before any plan exists; a
    // program carries the same terms, with the planned pieces where there are pieces.
    virtual RunTerms runTerms() const { return {}; }
    // Whether a key of the machine's own data (as the forms name it, without "machine.") is a
    // machine parameter - geometry, drives, gains, scaling, limits -, which only an engineer
    // may change; the machine's other keys are process parameters, a setter's
    // (core/machine/parameter_level.h judges the common sections).
    virtual bool isMachineParameter(const std::string& /*key*/) const { return false; }

    // Plans the cut of a valid job. jobText is kept in the program for the run log; options
    // report progress and cancel (a machine that plans in one go may ignore them). The plan
    // holds the machine's own data (its plan type) also when it is Infeasible, for drawing.
    virtual MachinePlan plan(const Job& job, const std::string& jobText = {},
                             const PlanOptions& options = {}) const = 0;
    // "variant" of the cut where the machine has one (the robot's method); Refused when the value
    // is not one of the machine's or the machine has none.
    virtual Outcome setVariant(Job& job, const std::string& variant) const;
    // The machine's cutting methods (its variants) side by side on one job, simulated offline
    // (`cutcell-cli compare`): Ok; Incomplete with the files when a method could not be
    // simulated (the message says which and why); Refused when the machine has none to compare.
    virtual Outcome compareMethods(const Job& job, MethodComparisonFiles* out) const;

    virtual std::vector<ExportInfo> exports() const = 0;
    // The contents of one export of a plan (text, or the PDF's bytes). Throws
    // std::invalid_argument for an unknown id or a plan that cannot give it.
    virtual std::string exportFile(const std::string& exportId, const Job& job,
                                   const MachinePlan& plan) const = 0;
    // exportFile with settings; the default ignores them (machines without templates).
    virtual std::string exportFileWith(const std::string& exportId, const Job& job,
                                       const MachinePlan& plan,
                                       const ExportSettings& /*settings*/) const {
        return exportFile(exportId, job, plan);
    }

    // The offline report of `cutcell-cli simulate` (JSON text) and a few lines for the
    // terminal: Ok; Incomplete with the report of a run that did not complete and why (the
    // command exits non-zero after writing it); Refused without a report when the machine has
    // none (it runs in the engine only) or the work is over its bound.
    virtual Outcome offlineReport(const Job& job, const MachinePlan& plan, std::string* json,
                                  std::string* text) const;
    // The machine's own figures for `cutcell-cli bench` (printed, never asserted), keys
    // prefixed by the machine; none by default.
    virtual void addBenchFigures(bool quick, json::Object& out) const {
        (void)quick;
        (void)out;
    }
    // Arm machines (`cutcell-cli fk` / `ik`): the torch of one arm for joint values (deg), and
    // every IK branch (each with its status) for a torch pose {x, y, z mm, tx, ty, tz} in the
    // machine's frame, as JSON. The default: Refused, "... is not an arm machine".
    virtual Outcome forwardKinematics(const Job& job, const std::string& arm,
                                      const std::vector<double>& jointsDeg, json::Value* out) const;
    virtual Outcome inverseKinematics(const Job& job, const std::string& arm,
                                      const std::vector<double>& pose, json::Value* out) const;
    // Tunes the drives' controllers of a valid job from the machine's model and writes the gains
    // into job: Ok with the figures for the operator (a table, one line per axis) in *text;
    // Refused with why, the job then unchanged: the key of the first issue of an invalid job, no
    // key when the job cannot be planned, "machine.kind" from the default (no tuning).
    virtual Outcome tuneControllers(Job& job, const TuneOptions& options, std::string* text) const;
    // File formats this machine turns into jobs (File -> Import..., `cutcell-cli
    // import-<name>`; core/machine/job_importer.h); none by default.
    virtual std::vector<JobImporter> importers() const { return {}; }
    // The report of an engine run (`cutcell-cli run`, the GUI's run) in the machine's units.
    virtual json::Value runReport(const Job& job, const MachinePlan& plan,
                                  const TrackingReport& report) const = 0;
};

} // namespace cutcell
