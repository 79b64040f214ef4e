#pragma once
// The section-steel cell in the 3D view: the section extruded with its root radii from the
// core's outline (section_outline.h) up to the (square or mitred) cut plane, the table it lies
// on, the 3R path arm and the 5-DOF groove arm with their torches posed from the joint vector
// (axes 0..2 and 3..7) by the core's kinematics (SteelCell), and the planned torch path of
// every pass (one point per knot of the plan, equally spaced in time; between two passes the
// path holds the last point). The flame burns at the torch of the arm that has left its park
// position (as the core's tip model decides).
#include "ui/view3d/scene_model.h"

namespace cutcell::section_steel {
struct SectionSteelSpec;
struct SteelPlan;
} // namespace cutcell::section_steel

namespace cutcell::view3d {

// Throws std::invalid_argument when the job holds no section-steel section.
SceneModel buildSectionSteelScene(const Job& job, const section_steel::SteelPlan* plan);

// The section as a closed triangle mesh: the outline polygon (fillets as arcs) from x = x0 to
// the cut plane of the spec's end cut (exposed for tests).
SurfaceMesh extrudeSection(const section_steel::SectionSteelSpec& spec, double x0);

// Counter-clockwise simple polygon -> triangles (ear clipping); exposed for tests.
std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Eigen::Vector2d>& poly);

} // namespace cutcell::view3d
