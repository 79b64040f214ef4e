#pragma once
// The quick-return cutter in the 3D view: frame, crank, rocker, link, slider with its tool and
// the workpiece, placed from the crank angle (axis 0, rad) by the core's forward kinematics
// (quick_return::mechanismPoints). The mechanism's plane is the world's x-z plane (the crank
// frame's y is up); depth separates the crank, the rocker and the link as on the machine.
#include "ui/view3d/scene_model.h"

namespace cutcell::view3d {

// Throws std::invalid_argument with the core's message when the mechanism or the profile
// cannot be built (the job's plan problem).
SceneModel buildQuickReturnScene(const Job& job);

} // namespace cutcell::view3d
