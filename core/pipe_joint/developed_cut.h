#pragma once
// The 2-axis NC pipe profile cutter of seed 002: the torch stands at the top of the pipe section
// on a linear X axis, the pipe turns in the chuck (A axis), and the cut is the composite of the
// two motions. The cut is sampled on the seed's grid: n = profile_cutter.steps_per_rev_a equal
// steps of the branch angle beta (see core/pipe_joint/multi_branch.h for the symbol
// mapping).
//
//  - cut.target = "branch": the saddle end of the branch pipe, turning in the chuck.
//      A = beta (deg, 0 .. 360 over one turn, a full revolution of the branch),
//      X = the seed's l: distance from the branch's fixed (chuck) end to the cut, with L chosen
//          so that the longest generatrix is branch_pipe.length_mm. With other_branches the cut
//          is the seed's minimum N over the main pipe and those branches.
//  - cut.target = "main": the hole in the main pipe (the branch's bore on the main pipe's outer
//      surface, as CutGeometry). A = alpha, the angle of the point about the main axis from the
//      branch side (+y), X = the seed's s = S + z, S = JointExtras::branch_position_mm.
//
// Surface speed along the cut is measured on the developed work surface:
// ds = sqrt(dX^2 + (R_w dA)^2), R_w = outer radius of the pipe being cut.
#include "core/common/types.h"
#include "core/job/job.h"
#include "core/pipe_joint/multi_branch.h"

#include <string>
#include <vector>

namespace cutcell {

struct ProfilePoint {
    double beta_deg = 0; // the seed's beta, grid parameter
    double phi_rad = 0;  // PipeIntersection's parameter (phi = beta + 90 deg)
    Vec3 p_main;         // the cut point on both pipes, main pipe frame
    double x_mm = 0;     // X axis
    double a_deg = 0;    // A axis (continuous, not wrapped)
    int pipe = 0;        // the pipe that sets the point: 0 = main, k = other_branches[k-1]
    // Kerf compensation only (profile_kerf.h): the edge's unit tangent on the work pipe, kept
    // with the torch point so that the edge comes back exactly; zero on an edge.
    Vec3 edge_tangent = Vec3::Zero();
};

struct ProfileCut {
    CutTarget target = CutTarget::Branch;
    double work_radius_mm = 0;        // R_w, outer radius of the pipe being cut
    double a_per_turn_deg = 360;      // A travel over the closed cut: 360 (branch end) or 0 (hole)
    std::vector<ProfilePoint> points; // n points, one turn, the first not repeated at the end
    std::vector<double> increments_x_mm; // the seed's N' (X increments, closing one included)
    // Kerf compensation (core/machines/profile_cutter/profile_kerf.h): the points are the torch
    // centre's, kerf_mm / 2 off the part's edge toward the scrap side; 0 = the edge itself.
    double kerf_mm = 0;
    std::string kerf_problem; // the job asked for a kerf that could not be compensated: why
    // Developed (surface) length of the closed polyline through the points.
    double developedLength() const;
    // Point i with i in [0, n]: i = n is the first point one turn later (A + a_per_turn_deg).
    ProfilePoint closedAt(size_t i) const;
};

// The cut of the job's joint with the extras (other branches, hole position) on n grid steps.
ProfileCut computeProfileCut(const Job& job, const JointExtras& extras, int n);

// The main frame intersection the cut is built on (outer surfaces for the branch end, the
// branch's bore for the hole), side +1.
IntersectionSpec profileIntersectionSpec(const Job& job);

// The other branches as joint pipes.
std::vector<JointPipe> jointPipes(const JointExtras& extras);

} // namespace cutcell
