#pragma once
// Who may change a key of a job (issue 25's user levels): a setter the process parameters
// (sizes, speeds, bevel, the cut), an engineer the machine parameters (the common sections
// engine, devices and sim: E-STOP category, limits, buses, the simulation; and what the
// machine's module calls a machine parameter: geometry, drives, gains, scaling). An operator
// changes no key: it opens jobs and runs them.
#include "core/record/audit.h"

#include <initializer_list>
#include <string>
#include <string_view>

namespace cutcell {

class MachineModule;

// `key` as the forms and validateJob() name it ("machine." is optional); `machine` the job's
// module (null: only the common sections are judged).
UserLevel levelToChange(std::string_view key, const MachineModule* machine);

// Whether `key` is one of `sections` or lies under one ("carriage" holds "carriage.stroke_mm"
// and "drives" holds "drives[2].kp"): the modules' isMachineParameter() in one line.
bool keyUnder(std::string_view key, std::initializer_list<std::string_view> sections);

} // namespace cutcell
