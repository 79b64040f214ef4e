#pragma once
// The machines the operator station knows, found by the id the job carries. Filled once, on
// first use, by registerMachineUis() (ui/machines/register_machine_uis.cpp): an explicit list,
// no static self-registration a linker could drop from a static library.
//
// Threading contract: the first call fills the registry under std::call_once; afterwards it is
// read-only and every function may be called from any thread.
#include "ui/machine/machine_ui.h"

#include <memory>
#include <string_view>
#include <vector>

namespace CutCell::ui {

class MachineUiRegistry {
  public:
    // Refuses a second module with the same id (std::logic_error: a programming error).
    void add(std::unique_ptr<MachineUi> machine);

  private:
    friend const std::vector<const MachineUi*>& machineUis();
    std::vector<std::unique_ptr<MachineUi>> owned_;
    std::vector<const MachineUi*> list_;
};

// Defined in ui/machines/register_machine_uis.cpp: one line per machine.
void registerMachineUis(MachineUiRegistry& registry);

// One more machine after the shipped ones (a machine outside this tree, a test's): at start-up,
// before the first window and before any other thread looks a machine up.
void registerMachineUi(std::unique_ptr<MachineUi> machine);
// Every machine, in registration order (the File -> New list).
const std::vector<const MachineUi*>& machineUis();
// The machine with this id; null when none (an unknown machine in a job file).
const MachineUi* findMachineUi(std::string_view id);
// The machine of a job; null when none.
const MachineUi* machineUiFor(const cutcell::Job& job);

} // namespace CutCell::ui
