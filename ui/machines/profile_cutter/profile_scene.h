#pragma once
// The 3D scene of the 2-axis NC pipe profile cutter (seed 002): the pipe being cut lies in the
// chuck along world X and turns with axis 0 (A, rad); the torch hangs radially (straight down)
// from a carriage on axis 1 (X, mm) over the pipe's top generatrix; the cut curve is drawn on
// the pipe.
//
// Work frame = the tip model's frame (core/machines/profile_cutter/profile_cutter_program.h): pipe
// axis z, z = X (0 at the carriage origin), A = 0 puts the work +y generatrix under the torch. The
// cut point of grid point i is (R_w sin A_i, R_w cos A_i, X_i), so with q = (A_i, X_i) the torch
// tip touches path point i.
#include "ui/view3d/scene_model.h"

namespace cutcell::view3d {

// Throws std::invalid_argument (core's message) when the job's cut cannot be computed.
SceneModel buildProfileCutterScene(const Job& job);

} // namespace cutcell::view3d
