#include "core/machine/parameter_level.h"

#include "core/machine/machine_module.h"

namespace cutcell {

bool keyUnder(std::string_view key, std::initializer_list<std::string_view> sections) {
    for (const std::string_view s : sections)
        if (key.substr(0, s.size()) == s &&
            (key.size() == s.size() || key[s.size()] == '.' || key[s.size()] == '['))
            return true;
    return false;
}

UserLevel levelToChange(std::string_view key, const MachineModule* machine) {
    constexpr std::string_view kMachine = "machine.";
    if (key.substr(0, kMachine.size()) == kMachine) key.remove_prefix(kMachine.size());
    if (keyUnder(key, {"engine", "devices", "sim"})) return UserLevel::Engineer;
    if (machine && machine->isMachineParameter(std::string(key))) return UserLevel::Engineer;
    return UserLevel::Setter;
}

} // namespace cutcell
