#pragma once
// Kerf compensation of the profile cutter's developed cut (issue 24). The torch stands radially
// over the pipe (square cut only), so the cut surface is radial and the torch centre runs k/2
// off the part's edge across it, on the pipe surface (core/process/kerf_offset.h, with the torch
// axis along the inward radius). Scrap: for the branch end the off-cut beyond the cut (larger
// X: the kept branch runs from the chuck to the cut), for the hole its inside.
#include "core/common/outcome.h"
#include "core/pipe_joint/developed_cut.h"

namespace cutcell {

// Moves every point of `cut` (the edge) to the torch centre for kerf `kerf_mm`, keeping beta,
// phi and p_main (the edge's) and recomputing the X increments; sets cut.kerf_mm. Refused, with
// the cut unchanged, when the kerf is too wide for the pipe or for the edge's curvature.
Outcome compensateProfileKerf(ProfileCut& cut, double kerf_mm);

// The edge back from a torch path made by compensateProfileKerf (the inverse, for checks).
Outcome profileEdgeFromTorch(ProfileCut& torch);

// Whether the scrap lies left of the travel (seen from outside the pipe; on the developed
// surface (X, R_w A) left of a direction (dX, dU) is (-dU, dX)): the side the kerf offset and
// the lead-in / lead-out (profile_lead.h) go to. The cut needs >= 3 points.
bool profileScrapOnLeft(const ProfileCut& cut);

} // namespace cutcell
