#include "ui/machine/machine_ui_registry.h"

#include "core/machine/machine_registry.h"
#include "ui/panels/engine_text.h"

#include <QObject>

#include <mutex>
#include <stdexcept>

namespace CutCell::ui {

void MachineUiRegistry::add(std::unique_ptr<MachineUi> machine) {
    for (const MachineUi* m : list_)
        if (m->id() == machine->id())
            throw std::logic_error("machine ui registered twice: " + machine->id());
    list_.push_back(machine.get());
    owned_.push_back(std::move(machine));
}

namespace {
MachineUiRegistry& theRegistry() {
    static MachineUiRegistry registry;
    static std::once_flag once;
    std::call_once(once, [] { registerMachineUis(registry); });
    return registry;
}
} // namespace

const std::vector<const MachineUi*>& machineUis() {
    return theRegistry().list_;
}

void registerMachineUi(std::unique_ptr<MachineUi> machine) {
    theRegistry().add(std::move(machine));
}

const MachineUi* findMachineUi(std::string_view id) {
    for (const MachineUi* m : machineUis())
        if (m->id() == id) return m;
    return nullptr;
}

const MachineUi* machineUiFor(const cutcell::Job& job) {
    // The core module decides which machine a job is for (schema-1 jobs without a machine key
    // get the default machine); the MachineUi is found by the module's id.
    const cutcell::MachineModule* module =
        job.machine.empty() ? cutcell::findMachine(cutcell::schema1DefaultMachine())
                            : cutcell::findMachine(job.machine);
    return module ? findMachineUi(module->id()) : nullptr;
}

std::vector<AxisLabel> MachineUi::axes() const {
    // One source of the axis names: the core module's (the same as the program's, the events'
    // and the reports'), with the unit of each axis.
    std::vector<AxisLabel> out;
    const cutcell::MachineModule* module = cutcell::findMachine(id());
    if (!module) return out;
    for (const cutcell::AxisInfo& a : module->axes(module->defaultJob()))
        out.push_back(
            {QString::fromStdString(a.name), QString::fromLatin1(cutcell::unitSymbol(a.unit))});
    return out;
}

const cutcell::MachineModule& MachineUi::module() const {
    const cutcell::MachineModule* m = cutcell::findMachine(id());
    if (!m) throw std::logic_error("no core machine module \"" + id() + "\" is registered");
    return *m;
}

cutcell::MachinePlan MachineUi::plan(const cutcell::Job& job,
                                     const cutcell::PlanOptions& options) const {
    cutcell::MachinePlan p = module().plan(job, {}, options);
    if (options.cancelled()) { // a plan finished as it was cancelled is dropped all the same
        p.outcome = cutcell::Outcome::cancel();
        p.program.reset();
    } else if (p.ok() && !p.program) {
        p.outcome = cutcell::Outcome::refuse("the machine module gave no program");
    }
    return p;
}

std::size_t MachineUi::plannedPointCount(const cutcell::MachinePlan& plan) const {
    return plan.program ? plan.program->point_count : 0;
}

QString MachineUi::planSummary(const cutcell::Job&, const cutcell::MachinePlan& plan) const {
    // In the GUI's language where core made it from a template (messageC).
    return engineText(QString::fromStdString(plan.summary));
}

std::shared_ptr<const cutcell::MotionProgram> programForRun(const cutcell::MachinePlan& plan,
                                                            const std::string& jobText) {
    if (!plan.ok() || !plan.program) throw std::invalid_argument(plan.outcome.message);
    auto program = std::make_shared<cutcell::MotionProgram>(*plan.program);
    program->source_text = jobText;
    return program;
}

std::string MachineUi::exportText(ExportKind, const cutcell::Job&, QString*) const {
    throw std::invalid_argument("this machine writes no such file");
}

QString exportLabel(ExportKind kind) {
    switch (kind) {
    case ExportKind::Gcode:
        return QObject::tr("Export &G-code...");
    case ExportKind::TemplateSvg:
        return QObject::tr("Export template (SVG)...");
    case ExportKind::TemplatePdf:
        return QObject::tr("Export template (PDF)...");
    }
    return {};
}

QString exportFilter(ExportKind kind) {
    switch (kind) {
    case ExportKind::Gcode:
        return QObject::tr("G-code (*.ngc *.nc *.gcode)");
    case ExportKind::TemplateSvg:
        return QStringLiteral("SVG (*.svg)");
    case ExportKind::TemplatePdf:
        return QStringLiteral("PDF (*.pdf)");
    }
    return {};
}

} // namespace CutCell::ui
