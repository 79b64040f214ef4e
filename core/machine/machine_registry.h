#pragma once
// The machines this CutCell knows. registerMachines() (core/machines/register_machines.cpp)
// holds the one explicit list; the lookups below call it once themselves, so no module depends
// on a static initialiser that the linker may drop from the static library.
#include "core/machine/machine_module.h"

#include <memory>
#include <string>
#include <vector>

namespace cutcell {

// Registers every shipped machine. Defined in core/machines/register_machines.cpp; called once
// by the first lookup below, never directly.
void registerMachines();
// Adds one module (called by registerMachines(); a machine from outside the tree after the
// first lookup, at start-up); a second module with the same id is refused.
void registerMachine(std::unique_ptr<MachineModule> module);

// nullptr when no module has this id.
const MachineModule* findMachine(const std::string& id);
// Every registered module, in registration order.
std::vector<const MachineModule*> machines();
// The module of job.machine; throws JobError naming the known ids when there is none.
const MachineModule& machineFor(const Job& job);
// The ids in quotes, comma-separated, for messages.
std::string machineIdList();
// The machine of a schema-1 file without a "machine" key (the first one registered).
std::string schema1DefaultMachine();

} // namespace cutcell
