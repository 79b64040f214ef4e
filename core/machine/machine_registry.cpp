#include "core/machine/machine_registry.h"

#include <mutex>

namespace cutcell {
namespace {

std::vector<std::unique_ptr<MachineModule>>& modules() {
    static std::vector<std::unique_ptr<MachineModule>> m;
    return m;
}

void ensureRegistered() {
    static std::once_flag once;
    std::call_once(once, [] { registerMachines(); });
}

} // namespace

void registerMachine(std::unique_ptr<MachineModule> module) {
    for (const auto& m : modules())
        if (m->id() == module->id())
            throw std::logic_error("machine module \"" + module->id() + "\" registered twice");
    modules().push_back(std::move(module));
}

const MachineModule* findMachine(const std::string& id) {
    ensureRegistered();
    for (const auto& m : modules())
        if (m->id() == id) return m.get();
    return nullptr;
}

std::vector<const MachineModule*> machines() {
    ensureRegistered();
    std::vector<const MachineModule*> out;
    for (const auto& m : modules())
        out.push_back(m.get());
    return out;
}

std::string schema1DefaultMachine() {
    ensureRegistered();
    return modules().empty() ? std::string() : modules().front()->id();
}

const MachineModule& machineFor(const Job& job) {
    const std::string id = job.machine.empty() ? schema1DefaultMachine() : job.machine;
    if (const MachineModule* m = findMachine(id)) return *m;
    throw JobError("machine.kind = " + json::quote(id) + " is not one of " + machineIdList());
}

std::string machineIdList() {
    std::string out;
    for (const MachineModule* m : machines())
        out += (out.empty() ? "\"" : ", \"") + m->id() + "\"";
    return out;
}

const char* unitSymbol(AxisUnit u) {
    return u == AxisUnit::Rotary ? "deg" : "mm";
}

const char* commandModeName(CommandMode m) {
    switch (m) {
    case CommandMode::Position:
        return "position";
    case CommandMode::Velocity:
        return "velocity";
    case CommandMode::Torque:
        return "torque";
    }
    return "position";
}

Outcome MachineModule::setVariant(Job&, const std::string& variant) const {
    return Outcome::refuse("machine " + json::quote(id()) + " has no cut variants (asked for " +
                           json::quote(variant) + ")");
}

Outcome MachineModule::compareMethods(const Job&, MethodComparisonFiles*) const {
    return Outcome::refuse("machine " + json::quote(id()) + " has no cutting methods to compare");
}

Outcome MachineModule::offlineReport(const Job&, const MachinePlan&, std::string*,
                                     std::string*) const {
    return Outcome::refuse("machine " + json::quote(id()) +
                           " has no offline report; it runs in the engine: cutcell-cli run JOB");
}

Outcome MachineModule::tuneControllers(Job&, const TuneOptions&, std::string*) const {
    return Outcome::refuse("machine " + json::quote(id()) +
                               " has no controller tuning; set its gains in the job",
                           "machine.kind");
}

Outcome MachineModule::forwardKinematics(const Job&, const std::string&, const std::vector<double>&,
                                         json::Value*) const {
    return Outcome::refuse("machine " + json::quote(id()) + " is not an arm machine (no fk)");
}

Outcome MachineModule::inverseKinematics(const Job&, const std::string&, const std::vector<double>&,
                                         json::Value*) const {
    return Outcome::refuse("machine " + json::quote(id()) + " is not an arm machine (no ik)");
}

} // namespace cutcell
