#pragma once
// A branch pipe cut to fit several pipes at one joint (seed 002, Section 3, "several pipes
// connecting together"): the set M, its minima N and the increments N'.
//
// Seed -> CutCell mapping (all in the main pipe frame of core/geometry/pipe_intersection.h):
//   R, r, theta, e      -> IntersectionSpec main_radius_mm, branch_radius_mm, angle_deg,
//                          eccentricity_mm of the CUT branch;
//   beta (branch turn)  -> phi = beta + 90 deg (cos beta = sin phi, sin beta = -cos phi), so the
//                          seed's R sin(alpha) = r cos(beta) + e is PipeIntersection's
//                          x = e + r sin(phi), and R cos(alpha) is its y;
//   Eq. (1)/(2) halves  -> the two roots y = +-sqrt(R^2 - x^2) (IntersectionSpec::side);
//   l (Eq. 3)           -> l = L - t, t = PipeIntersection::branchAxial (seed: DP = t);
//   s (Eq. 4)           -> s = S + z of the point on the main pipe.
//
// M has one row per rotation step of the cut branch (n rows, the seed's grid of the stepper's
// pulse angle) and one column per pipe it meets (column 0 = main pipe, column k = other branch
// k-1). M(i, j) is the l of the "peak": the meeting point of generatrix i with pipe j nearest to
// the fixed end. The seed then takes, for each rotation step, the smallest l over the pipes
// (the seed's "smallest value in every column" with its M written one pipe per column, the
// row index C_i naming the pipe): N(i) = min_j M(i, j), c(i) = argmin. The cut branch thereby
// ends on the first pipe surface it meets coming from its fixed end, so it fits every pipe.
// N'(i) = N(i+1) - N(i), N'(n-1) = N(0) - N(n-1): over one turn they sum to zero (closed cut).
#include "core/common/types.h"
#include "core/geometry/pipe_intersection.h"
#include "core/job/job.h"
#include "core/pipe_joint/pipe_joint_extras.h"

#include <optional>
#include <utility>
#include <vector>

namespace cutcell {

// An infinite cylinder of which only the half outward of axis_point (along axis_dir) is real
// pipe: a branch welded onto the main pipe, with axis_point where its axis enters the main pipe.
struct JointPipe {
    Vec3 axis_point; // main frame
    Vec3 axis_dir;   // unit, pointing out of the main pipe
    double radius_mm = 0;
};

// The other branch of a job in the main frame (see OtherBranch in pipe_joint_extras.h).
JointPipe jointPipeFrom(const OtherBranch& b);

// Where the generatrices of the cut branch meet one other branch. Built from PipeIntersection
// in a frame of the other pipe (its axis = z, the common perpendicular = x), so the crossing
// uses the same formula as the main pipe.
class BranchCrossing {
  public:
    // Throws std::invalid_argument when the axes are parallel.
    BranchCrossing(const PipeIntersection& cutBranch, const JointPipe& pipe, double mainRadius);
    // The meeting point (main frame) of generatrix phi nearest to the cut branch's fixed end
    // (largest t) that lies on the real part of the pipe and outside the main pipe; none if
    // the generatrix misses it.
    std::optional<Vec3> meet(double phi) const;
    const JointPipe& pipe() const { return pipe_; }

  private:
    // The other pipe's frame (main from local) and the crossing seen from it.
    using LocalFrame = std::pair<Pose, IntersectionSpec>;
    BranchCrossing(const PipeIntersection& cutBranch, const JointPipe& pipe, double mainRadius,
                   const LocalFrame& frame);
    static LocalFrame localFrame(const PipeIntersection& cut, const JointPipe& pipe);

    const PipeIntersection* cut_;
    JointPipe pipe_;
    double mainRadius_;
    Pose mainFromLocal_;
    PipeIntersection localPlus_, localMinus_;
};

struct SetM {
    int rows = 0;                // n rotation steps
    int cols = 0;                // pipes: 0 = main, k = other branch k-1
    double L_mm = 0;             // the seed's L: l = L - t
    std::vector<double> phi_rad; // per row
    std::vector<double> l;       // row-major rows x cols; NaN where the generatrix misses
    std::vector<Vec3> point;     // the meeting points (main frame), NaN where missed
    double at(int i, int j) const { return l[static_cast<size_t>(i * cols + j)]; }
    const Vec3& pointAt(int i, int j) const { return point[static_cast<size_t>(i * cols + j)]; }
};

// n rows at phi = phi0 + 2 pi i / n. cutBranch: main frame, side +1 (the branch on y > 0).
SetM buildSetM(const PipeIntersection& cutBranch, const std::vector<JointPipe>& others, double L_mm,
               int n, double phi0);

struct ColumnMinima {
    std::vector<double> N;       // n processing lengths (mm)
    std::vector<int> c;          // which pipe sets each one
    std::vector<double> N_prime; // n increments (mm), closed: sum = 0
};

ColumnMinima columnMinima(const SetM& m);

} // namespace cutcell
