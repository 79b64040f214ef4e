#include "devices/machines/sim_rig_registry.h"

#include "core/machine/machine_registry.h"
#include "core/machines/flying_saw/flying_saw_module.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"
#include "core/machines/quick_return/quick_return_spec.h"
#include "core/machines/section_steel/section_steel_module.h"
#include "devices/machines/sim_rigs.h"

namespace cutcell {
namespace {

using Factory = std::unique_ptr<MachineSimRig> (*)(const Job&, const MotionProgram&);

// One line per machine.
const struct {
    const char* machine;
    Factory make;
} kRigs[] = {
    {kPipeRobotId, makePipeRobotSimRig},
    {kProfileCutterId, makeProfileCutterSimRig},
    {kQuickReturnId, makeQuickReturnSimRig},
    {kFlyingSawId, makeFlyingSawSimRig},
    {kSectionSteelId, makeSectionSteelSimRig},
};

} // namespace

std::unique_ptr<MachineSimRig> makeSimulatedRig(const Job& job, const MotionProgram& program,
                                                std::string* error) {
    const std::string id = machineFor(job).id();
    for (const auto& r : kRigs)
        if (id == r.machine) {
            try {
                return r.make(job, program);
            } catch (const std::exception& e) {
                if (error) *error = e.what();
                return nullptr;
            }
        }
    if (error) *error = "machine " + json::quote(id) + " has no simulated devices";
    return nullptr;
}

} // namespace cutcell
