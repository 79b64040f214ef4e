// The simulated rigs: one line per machine (README, "Adding a machine").
#include "sim_rigs.h"

#include "pipe_robot_6axis/sim_rig.h"
#include "profile_cutter_2axis/sim_rig.h"
#include "ui/machines/pipe_robot_6axis/pipe_robot_ui.h"
#include "ui/machines/profile_cutter_2axis/profile_cutter_ui.h"

namespace cutcell::app {

CutCell::ui::EngineRigFactory simulatedRigFor(std::string_view machineId) {
    struct Entry {
        const char* id;
        CutCell::ui::EngineRigFactory make;
    };
    static const Entry rigs[] = {
        {CutCell::ui::PipeRobotUi::kId, &makePipeRobotSimRig},
        {CutCell::ui::ProfileCutterUi::kId, &makeProfileCutterRig},
    };
    for (const Entry& e : rigs)
        if (machineId == e.id) return e.make;
    return {};
}

} // namespace cutcell::app
