#pragma once
// The torch path of an end cut: the section's outline in the (square or mitred) cut plane, the
// torch at every point perpendicular to the cut edge and pointing into the material, tilted by
// the groove angle towards the bar end (in the plane normal to the cut edge). Pass "square"
// separates the bar (tilt 0); pass "groove" follows the outline again with the bevel on the
// faces that have one (the tilt ramps in and out over blend_mm; fillets and toes stay square).
// At sharp corners (toes) the torch turns about its tip at reorient_deg_s; on radii tighter than
// speed / reorient (toe radii, small fillets) the tip slows so that the torch turns no faster.
// Setup 2 (section turned over): only the groove passes of the bevels setup 1 could not reach.
#include "core/common/types.h"
#include "core/machines/section_steel/section_outline.h"
#include "core/machines/section_steel/section_steel_spec.h"
#include "core/machines/section_steel/torch_clearance.h"

#include <string>
#include <vector>

namespace cutcell::section_steel {

struct TorchTarget {
    Vec3 p{0, 0, 0};      // tip, world (mm): the torch centre (kerf compensated, section_kerf.h)
    Vec3 edge_p{0, 0, 0}; // the theoretical edge's point: p without the kerf compensation
    Vec3 t{0, 0, 0};      // torch direction into the material, world (unit)
    Vec3 edge{0, 0, 0};   // cut edge direction (unit), world
    Vec3 t0{0, 0, 0};     // the untilted direction (in the cut plane, normal to the edge)
    Vec2 yz{0, 0};        // point of the outline (the tip without the bevel offset)
    double tilt_rad = 0;  // groove tilt at this point
    double lean_rad = 0;  // lean along the edge (in the cut / bevel surface), clears the body
    double s_mm = 0;      // along the outline
    size_t segment = 0;   // outline segment (face)
    bool turning = false; // torch turning at a sharp corner (tip at rest)
    // A lead's sample (section_lead.h): 0 the cut itself, 1 the pierce (firing at pierce height
    // and going down to cut height), 2 the lead-in, 3 the lead-out.
    int lead = 0;
};

struct CutPass {
    std::string name; // "square", "groove"
    bool groove_arm = false;
    std::vector<TorchTarget> samples; // at equal time steps dt
    double duration_s = 0, length_mm = 0;
};

class EndCut {
  public:
    EndCut(const SectionSteelSpec& spec);
    const SectionOutline& outline() const { return outline_; }
    // x of the cut plane at (y, z) and its unit normal (towards the bar end, +x).
    double planeX(double y, double z) const;
    Vec3 planeNormal() const;
    bool square() const { return square_; }
    // Setup 2 (end_cut.setup): the section turned over, its outline and cut plane mirrored
    // (SectionOutline), only the bevels setup 1 could not cut (grooveOf), no square pass.
    bool turnedOver() const;
    bool hasGroove() const;
    // The groove spec of an outline segment and whether this face is bevelled.
    const GrooveSpec* grooveOf(size_t segment) const;
    // The passes of the cut, sampled every dt seconds.
    std::vector<CutPass> passes(double dt) const;
    // The target at outline length s of a pass with the given groove scale (0..1 ramps).
    TorchTarget target(const OutlinePoint& o, double s, bool groovePass) const;

    // The torch body of the spec (torch_length_mm, torch_radius_mm).
    TorchBody torchBody() const { return {spec_.torch_length_mm, spec_.torch_radius_mm}; }

  private:
    // Leans the torch where its body would hit the section: the smallest lean (2 deg steps
    // up to max_lean_deg), then ramped in and out at reorient_deg_s.
    void applyLean(CutPass& pass, double dt) const;
    double tiltAt(size_t segment, double s, double* depth) const;
    SectionSteelSpec spec_;
    SectionOutline outline_;
    double tanV_, tanH_;
    bool square_;
};

// Why setup 2 (end_cut.setup = 2) has nothing to cut for this spec, naming the keys; "" when
// it has a bevel to cut or the spec is setup 1. Setup 2 exists for the K groove's second bevel
// on the face that lies on the conveyor in setup 1.
std::string setupTwoProblem(const SectionSteelSpec& spec);

} // namespace cutcell::section_steel
