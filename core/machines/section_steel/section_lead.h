#pragma once
// Lead-in / lead-out and pierce height of the section-steel end cut (issue 24: process.lead_in,
// process.lead_out {kind: line | arc | none, length_mm, overlap_mm}; pierce and cut height from
// the cut chart's row or an override).
//
// How the cut path is formed, and what that means for the leads:
// - The square (or mitred) pass, the only one that separates the bar, is OPEN: it starts at the
//   right end of the table face (the bottom flange's / horizontal leg's toe at z = 0) and runs
//   round the outline to its left end (z = 0 again); the face on the conveyor is not cut from
//   above. Both ends are free edges over the slag bin (no table beneath the cut zone). There is
//   no start to overlap: process.lead_out.overlap_mm is refused on this machine.
// - The groove passes (groove arm, face by face) are open too and start and end where the bevel
//   has ramped to 3 deg, a strip narrower than the kerf at the bar's end: they start off the
//   material and get no leads. Setup 2 (turned over) has only groove passes: leads are refused.
// - The path arm is a planar 3R arm in the (kerf-shifted) cut plane, with no axis along the bar:
//   every point it can reach lies in that plane, exactly k/2 across the cut surface on the scrap
//   side. A lead in the start face's plane square to the cut (along the bar) is out of its reach,
//   so the leads lie in the arm's plane, off the material past the free edges:
//     lead-in "line": straight on along the cut's start tangent, length_mm before the start
//       (a run-on from below the free edge onto the start: it lies in the start face's plane
//       and in the arm's plane);
//     lead-in "arc": a quarter circle of arc length length_mm (radius 2 L / pi) in the arm's
//       plane joining the cut tangentially at its start, curving away from the material (out of
//       the face, behind the nozzle);
//     lead-out: the same past the cut's end (run-off along its end tangent, or a quarter arc
//       curving away from the material).
//   Every lead point is therefore k/2 across the cut surface (on the scrap side, at k/2 from the
//   part's edge) and off the material (z <= 0 in the section's frame, or outside its outline).
// - Pierce: a lead-in that starts off the material's edge needs no pierce (the arc transfers as
//   the torch reaches the edge: an edge start). The torch is fired at the pierce height above
//   the lead-in's first point along its axis, with no pierce delay (nothing to pierce), then
//   moves down along the torch axis to the cut height and runs the lead. Heights: the plan's
//   tool point (TorchTarget::p) is where the torch axis meets the (extended) surface; the nozzle
//   stands the cut height behind it (the standoff is in the tool). At the pierce height the tool
//   point is therefore (pierce - cut height) back along the torch axis and the nozzle the pierce
//   height above the surface.
// - A lead too long for the cell (a lead point out of the path arm's reach or joint limits, or
//   the torch body hitting the section there) is refused with the key, value, unit and the
//   longest length that fits (SteelPlan::lead_problem).
// - No lead keys: nothing is added (the plan and path.csv bit for bit as before).
#include "core/job/job.h"
#include "core/machines/section_steel/end_cut_path.h"
#include "core/process/process_spec_data.h"

#include <string>
#include <vector>

namespace cutcell::section_steel {

enum LeadRole : int { kLeadNone = 0, kLeadPierce = 1, kLeadIn = 2, kLeadOut = 3 };

// What the plan needs of the job's leads.
struct SteelLeadSpec {
    LeadSpec in, out;
    double pierce_height_mm = 0, cut_height_mm = 0;
    bool used() const { return in.used() || out.used(); }
};

struct SteelLeadRequest {
    SteelLeadSpec spec;
    std::string problem; // the leads cannot be asked for here: why (key, value, unit)
    std::string problem_key;
};

// The job's leads (unused without lead keys). Refused: the process does not resolve, a height
// is missing (leadHeightProblem), an overlap (open cut), setup 2 (no square pass).
SteelLeadRequest steelLeadRequest(const Job& job);

// The lead-in's points (tool points, the first one first) ending before the cut's start `start`
// (a torch centre, kerf compensated), and the lead-out's after the end `end`. Line: one point
// (the lead's far end); arc: kLeadArcSegments points along the quarter arc.
inline constexpr int kLeadArcSegments = 16;
std::vector<Vec3> steelLeadInPoints(const TorchTarget& start, LeadKind kind, double length_mm);
std::vector<Vec3> steelLeadOutPoints(const TorchTarget& end, LeadKind kind, double length_mm);
// The travel direction of the cut at its start / end (unit, in the cut plane).
Vec3 steelCutTangent(const TorchTarget& t);
// The direction away from the material in the arm's plane at a target: -t0 (behind the nozzle).
Vec3 steelAwayFromMaterial(const TorchTarget& t);

// The samples the leads add to the square pass, dt apart (each stretch from rest to rest at the
// cutting speed with the pass's ramps): the pierce (tool point (pierce - cut height) back along
// the torch axis over the lead-in's first point, down to it), the lead-in, the pass itself, the
// lead-out. The lead samples keep the start's (end's) torch direction, edge, lean and face.
struct SteelLeadSamples {
    std::vector<TorchTarget> before, after;
    double before_s = 0, after_s = 0;       // their durations
    double lead_in_mm = 0, lead_out_mm = 0; // path lengths of the leads (pierce move excluded)
    Vec3 pierce_point{0, 0, 0};             // the lead-in's first point (on the surface's plane)
    Vec3 pierce_nozzle{0, 0, 0};            // the nozzle at the pierce height above it
};
SteelLeadSamples steelLeadSamples(const SectionSteelSpec& spec, const CutPass& square,
                                  const SteelLeadSpec& leads, double dt);
// The square pass with its leads (pass.samples, duration_s; length_mm stays the cut's).
void addSteelLeads(CutPass& square, const SteelLeadSamples& leads);

} // namespace cutcell::section_steel
