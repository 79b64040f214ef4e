#pragma once
// The operator station's side of one machine (LinuxCNC's kinematics modules, ros2_control's
// hardware plugins: one interface, one implementation per machine, chosen by the job's machine
// id). Everything the GUI shows or does differently per machine comes from here: the form pages
// it adds to the parameter tabs, the common fields it does not use, its 3D scene, its plot
// channels (axis names and units), the exports it offers, its planning and motion program, and
// the default job File -> New creates for it. Each machine lives in ui/machines/<id>/ and is
// listed once in registerMachineUis() (ui/machines/register_machine_uis.cpp).
//
// The simulated devices are not here: the ui never includes a device header. The composition
// root (app/gui) keeps its own list of simulated rigs per machine (app/gui/machines/).
//
// One plan type flows from the machine's core module through the GUI to the engine: the
// module's MachinePlan (its program, summary and problem; its own data for its scene).
//
// Threading contract: a MachineUi is immutable after registration. plan() and
// plannedPointCount() are pure and callable from any thread (PlanWorker calls plan() on a pool
// thread); everything returning or creating widgets is GUI-thread only.
#include "core/engine/motion_program.h"
#include "core/job/job.h"
#include "core/machine/machine_module.h"
#include "core/pipe_joint/pipe_joint_extras.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cutcell::view3d {
struct SceneModel;
}

namespace CutCell::ui {

class JobEditor;
class JobForm;

// One axis as the operator reads it: its name on the plots and readouts and its unit. Rotary
// axes are "deg" (the engine's rad converted), linear axes "mm" (the engine's values as is).
struct AxisLabel {
    QString name; // e.g. "A chuck", "X carriage", "q3 elbow"
    QString unit; // "deg" or "mm"
    bool linear() const { return unit == QLatin1String("mm"); }
};

// What the Cartesian (tool tip) error plot shows for this machine.
enum class TipErrorPlot {
    None,       // no tip model: no Cartesian plot
    BaseXyz,    // x, y, z of FK(actual) - FK(setpoint) in the machine's base frame (mm)
    MissOnPipe, // the torch's miss on the pipe surface |e| (mm): the tip model's frame turns
                // with the pipe, its x/y/z mean nothing to the operator
};

// A form page the machine adds to the parameter tabs (after the common Pipes and Cut pages).
struct FormPage {
    QString title; // the tab title, translated, '&&' for '&'
    std::function<JobForm*(JobEditor*)> make;
};

enum class ExportKind { Gcode, TemplateSvg, TemplatePdf };

class MachineUi {
  public:
    virtual ~MachineUi() = default;

    // The machine id the job carries (Job::machine), unique in the registry.
    virtual std::string id() const = 0;
    // For the File -> New list and the status line, e.g. "Pipe-cutting robot (6 axes)".
    virtual QString title() const = 0;
    // The job File -> New creates for this machine.
    virtual cutcell::Job defaultJob() const = 0;

    // Pages of this machine's own keys; built once per ParameterTabs and shown only while the
    // job is for this machine.
    virtual std::vector<FormPage> formPages() const = 0;
    // Common fields (Pipes, Cut, ...) this machine ignores, with the reason for the tooltip.
    virtual std::vector<std::pair<std::string, QString>> unusedCommonFields() const { return {}; }

    // The axes in engine order (axis i of the telemetry): by default the core module's names
    // and units, so the DRO, the plots, the events and the reports name an axis alike.
    virtual std::vector<AxisLabel> axes() const;
    virtual TipErrorPlot tipErrorPlot() const = 0;

    // The exports of its Export menu (a robot job has no G-code).
    virtual std::vector<ExportKind> exports() const = 0;
    // The text of a machine-specific export (G-code); the cutting templates are common.
    // Throws std::exception with the core's message; *what describes the file for the log.
    virtual std::string exportText(ExportKind kind, const cutcell::Job& job, QString* what) const;
    // The pipe joint's other branches and hole position for the cutting templates (Template*
    // exports): none by default.
    virtual cutcell::JointExtras jointExtras(const cutcell::Job&) const { return {}; }

    // The core module of this machine's id (throws std::logic_error when none is registered).
    const cutcell::MachineModule& module() const;

    // Plans the job off the GUI thread: the core module's plan (Ok with its program, Infeasible
    // with the problem sentence, Cancelled when options.cancel was set).
    virtual cutcell::MachinePlan plan(const cutcell::Job& job,
                                      const cutcell::PlanOptions& options) const;
    // Planned points for the progress panel: the program's.
    std::size_t plannedPointCount(const cutcell::MachinePlan& plan) const;
    // The log line after a successful plan: the module's summary in the GUI's language.
    virtual QString planSummary(const cutcell::Job& job, const cutcell::MachinePlan& plan) const;

    // The 3D scene of the cell for a plan; false (and *why) when there is nothing to draw or
    // this build has no 3D view. Defined only where CUTCELL_HAVE_VIEW3D is.
    virtual bool buildScene(const cutcell::Job& job, const cutcell::MachinePlan& plan,
                            cutcell::view3d::SceneModel* out, QString* why) const = 0;
};

// The program of a plan for one run: the plan's program (made off the GUI thread, before the
// job was saved) with jobText for the run log. Throws std::invalid_argument with the plan's
// problem when it has no program.
std::shared_ptr<const cutcell::MotionProgram> programForRun(const cutcell::MachinePlan& plan,
                                                            const std::string& jobText);

// The ExportKind's menu label and file filter (common to every machine).
QString exportLabel(ExportKind kind);
QString exportFilter(ExportKind kind);

} // namespace CutCell::ui
