#include "sim_rig.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"

#include "can_rig.h"
#include "machines/sim_rigs.h"

namespace cutcell::app {

std::unique_ptr<CutCell::ui::EngineRig> makeRig(const Job& job, ClockMode clock,
                                                std::string* error) {
    if (job.devices.kind == DeviceKind::CanOpen) return makeCanRig(job, error);
    if (job.devices.kind != DeviceKind::Simulated) {
        if (error)
            *error = std::string("devices.kind = \"") + toString(job.devices.kind) +
                     "\": this build of cutcell drives the simulated cell only";
        return nullptr;
    }
    const auto make = simulatedRigFor(job.machine);
    if (!make) {
        if (error) *error = "no simulated rig for machine = \"" + job.machine + "\"";
        return nullptr;
    }
    return make(job, clock, error);
}

} // namespace cutcell::app
