#pragma once
// The flying saw in the 3D view: the tube on its roller tables moving along +x with the line
// (the telemetry's master position, SceneModel::masterSlot), the measuring roller on it, the
// carriage on its rail (axis 0, mm from the rail's zero), the turntable ring on the carriage and
// its two blades with their spindles on radial feed arms: blade i at the turntable angle
// (axis 1, rad) plus i half turns, its tip at the retracted radius minus its feed (axes 2, 3).
// A cut k's joint is drawn where the pipe was at the carriage's sync position when the master
// was at S_k (the plan's sync positions), once the blades left the wall; a cut piece is shown
// pulled away by the run-out table (a drawing aid: up to 250 mm, a quarter of the line's travel
// since its cut). The pipe is drawn over a window around the cell. Units mm, rad; z up.
#include "core/machine/machine_module.h"
#include "ui/view3d/scene_model.h"

namespace cutcell::view3d {

// Throws std::invalid_argument with the plan's problem when the job cannot be planned.
SceneModel buildFlyingSawScene(const Job& job, const MachinePlan& plan);

// The slot of q that carries the master position (the line encoder, mm) in this scene.
inline constexpr int kFlyingSawMasterSlot = kMaxAxes - 1;

} // namespace cutcell::view3d
