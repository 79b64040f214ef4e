#include "core/machines/section_steel/section_steel_spec.h"

namespace cutcell::section_steel {

SectionSteelSpec defaultSectionSteelSpec() {
    SectionSteelSpec s;
    s.section = *findSection("IPE 300");
    // Square end (path arm). Grooves: see README (the groove arm's layout is not settled).
    s.groove_base_x_mm = 0;
    s.groove_base_y_mm = -900;
    s.groove_base_z_mm = 1200;
    // Wrist joints turn the torch round the whole outline: +-270 deg (hose pack).
    s.path_limits = {{{-180, 0}, {-170, 170}, {-270, 270}}};
    s.groove_limits = {{{-270, 270}, {-270, 270}, {-270, 270}, {-270, 270}, {-270, 270}}};
    s.park_deg = {-60, 90, 60, 0, 0, 0, 0, 0};
    const PidGains big{3240, 64800, 53, 0.002}, wrist{1080, 21600, 17.5, 0.002};
    const JointPlantParams bigPlant{0.3, 1.0, 60}, wristPlant{0.1, 0.5, 30};
    for (size_t i = 0; i < kSteelAxes; ++i) {
        const bool isWrist = i == 2 || i >= 5;
        s.controller[i] = isWrist ? wrist : big;
        s.plant[i] = isWrist ? wristPlant : bigPlant;
    }
    return s;
}

} // namespace cutcell::section_steel
