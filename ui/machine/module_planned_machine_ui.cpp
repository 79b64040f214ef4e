#include "ui/machine/module_planned_machine_ui.h"

#include "core/machine/machine_module.h"
#include "core/machine/machine_registry.h"
#include "core/process/cut_chart.h"

namespace CutCell::ui {

cutcell::Job ModulePlannedMachineUi::defaultJob() const {
    return module().defaultJob();
}

std::vector<std::pair<std::string, QString>>
ModulePlannedMachineUi::pipeJointFields(const QString& why) {
    std::vector<std::pair<std::string, QString>> out;
    for (const char* pipe : {"main_pipe", "branch_pipe"})
        for (const char* field : {".radius_mm", ".wall_mm", ".length_mm"})
            out.push_back({std::string(pipe) + field, why});
    for (const char* key :
         {"angle_deg", "eccentricity_mm", "cut.target", "cut.bevel_deg", "cut.speed_mm_s",
          "cut.ramp_s", "cut.knot_spacing_mm", "cut.max_direction_deviation_deg",
          "cut.start_phi_auto", "cut.start_phi_deg"})
        out.push_back({key, why});
    // The process section is read with the pipe joint (core/machine/pipe_joint_section.h).
    for (const char* key : {"process.used", "process.process", "process.material",
                            "process.consumable", "process.thickness_mm"})
        out.push_back({key, why});
    for (std::size_t k = 1; k < cutcell::kCutFigureCount; ++k)
        out.push_back({std::string("process.override.") +
                           cutcell::cutFigureInfo(static_cast<cutcell::CutFigure>(k)).key,
                       why});
    return out;
}

} // namespace CutCell::ui
