#pragma once
// The pipe-cutting robot of seed 000 in the 3D view: work pipe in the chuck (axis 0), 5-DOF arm
// (axes 1..5). Path points are the plan's knots; a point is unreachable when the plan says the
// chuck is past its range, the IK failed, or the torch had to tilt more than allowed.
#include "core/machines/pipe_robot/cut_planner.h"
#include "ui/view3d/scene_model.h"

namespace cutcell::view3d {

SceneModel buildRobotScene(const Job& job, const CutPlan& plan);

} // namespace cutcell::view3d
