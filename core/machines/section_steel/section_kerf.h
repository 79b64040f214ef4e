#pragma once
// Kerf compensation of the section-steel end cut (issue 24). The torch burns a slot of width k
// centred on its axis; the torch centre runs k/2 off the theoretical edge, measured across the
// cut surface, toward the scrap side, so that the slot's near face is the theoretical cut.
//
// - Scrap: what lies past the cut surface toward the bar end (+m, m = EndCut::planeNormal()):
//   the off-cut for the square or mitred pass, the groove's wedge for a bevel pass.
// - Cut surface at a target: the plane spanned by the cut edge (TorchTarget::edge) and the torch
//   axis (TorchTarget::t; its lean along the edge stays in it): the cut plane itself on the square
//   pass, the bevel surface on a groove pass (tilt beta: across = cos(beta) m - sin(beta) u).
// - Construction (core/process/kerf_offset.h, offsetOnPrism): the section is a prism along the
//   bar (x), so the torch centre moves along x by (k/2) / (x . n), n the cut surface's normal:
//   it stays exactly on the section's surface, on a face, a root fillet, a toe radius or at a
//   corner the torch turns about, and the torch axis lies in the plane k/2 off the cut surface.
//   On a square end: k/2 for the square pass, (k/2) / cos(beta) along the face for a bevel.
// - The square (or mitre) pass stays in one plane, k/2 off the cut plane: the path arm (a planar
//   3R arm) cuts it with its plane moved by (k/2) / (x . m) along the bar (SteelCell's kerf:
//   both arms' mitre frame stands that much toward the off-cut - on the cell, the infeed sets the
//   bar that much short of the cut it would set without compensation).
// - No limit from a root fillet or a toe radius: on those the cut surface is the cut plane and
//   the move along the prism's lines is exact at any radius (no offset of the outline itself).
//   The limit is the bevel's: at full tilt the torch centre must stay on the face it bevels, i.e.
//   (k/2) / (x . n) <= the strip the bevel takes off the face (D tan(beta) on a square end, D the
//   groove's depth: k <= 2 D sin(beta)); past it the torch would run beyond the bar's end, the
//   whole arc over air. Where the tilt ramps in and out (motion.blend_mm) the strip narrows to
//   the pass's ends and the torch may overhang there, as a plate's edge is bevelled.
#include "core/common/outcome.h"
#include "core/job/job.h"
#include "core/machines/section_steel/end_cut_path.h"

#include <vector>

namespace cutcell::section_steel {

// The plate that picks the cut chart's row unless process.thickness_mm is given: the thickest
// the torch cuts through (flange or web).
double steelPartThicknessMm(const SectionSteelSpec& spec);

// The kerf the job's process section gives (the chart row at the part's plate or its override);
// 0 without the section, or when the chart refuses it (validation says why).
double steelKerfMm(const Job& job);

// How far the square / mitre pass's plane moves along the bar (x) for kerf k: (k/2) / (x . m).
double squarePassShiftMm(const EndCut& cut, double kerf_mm);

// Moves every target of the passes to the torch centre for kerf `kerf_mm` (TorchTarget::p; the
// theoretical edge point stays in TorchTarget::edge_p, the direction, edge, tilt, lean, s and
// timing are kept). k = 0 leaves the passes untouched. Refused, with the passes unchanged, when
// a target has no cut surface or the kerf is too wide for a bevel (the message names the value,
// the unit, the limit and the groove's key).
Outcome compensateSteelKerf(const EndCut& cut, std::vector<CutPass>& passes, double kerf_mm);

// The edge back from a torch path made by compensateSteelKerf (the inverse, for checks): moves
// TorchTarget::p back by k/2 across the cut surface of the stored edge and torch direction.
Outcome steelEdgeFromTorch(const EndCut& cut, std::vector<CutPass>& torch, double kerf_mm);

} // namespace cutcell::section_steel
