#pragma once
// What a pipe joint may hold beyond the job's common part (the two pipes, the angle, the
// eccentricity and the cut): more branch pipes meeting the cut branch, and where on the main
// pipe its hole lies. The developed cut and the cutting templates take them; a machine whose
// section has none (the pipe robot) gives the defaults.
#include <vector>

namespace cutcell {

// Another branch pipe at the same joint (seed 002: "several pipes connecting together"). The
// cut branch (branch_pipe, angle_deg, eccentricity_mm) is cut to fit the main pipe AND these.
// Main pipe frame (see core/geometry/pipe_intersection.h): this branch's axis passes through
// Rz(phase) * (eccentricity, 0, position) with outward direction Rz(phase) * (0, sin a, cos a).
struct OtherBranch {
    double radius_mm = 0;       // outer radius
    double angle_deg = 90;      // between its axis and the main axis, (0, 180)
    double eccentricity_mm = 0; // |e| + radius <= main radius
    double position_mm = 0;     // along the main axis, from the cut branch's axis crossing
    double phase_deg = 0;       // about the main axis; 0 = on the cut branch's side
};

struct JointExtras {
    std::vector<OtherBranch> other_branches; // the cut branch fits these too (cut = "branch")
    // Hole cut: X of the branch axis crossing (the seed's S) from the main pipe's fixed end;
    // automatic = the middle of the main pipe.
    bool branch_position_auto = true;
    double branch_position_mm = 0;
};

} // namespace cutcell
