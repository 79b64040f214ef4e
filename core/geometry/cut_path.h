#pragma once
// The cut as the torch sees it: the intersection curve on the pipe being cut (the "work
// pipe", held in the chuck), its arc length, and the cutting direction at every point.
//
// Work frame: the work pipe's axis is z (it becomes the chuck axis), and z = 0 is the middle
// of the cut. For the hole in the main pipe the work frame is the main frame shifted along z;
// for the saddle end of the branch it is the branch frame (x = main x, y = branchY, z = b).
//
// Surfaces: the branch end is the branch's outer surface meeting the main pipe's outer
// surface; the hole is the branch's bore (outer radius - wall) on the main's outer surface.
#include "core/common/types.h"
#include "core/geometry/pipe_intersection.h"
#include "core/job/job.h"

#include <vector>

namespace cutcell {

struct CutPoint {
    double phi_rad = 0;
    double s_mm = 0;    // arc length from the start of the cut
    Vec3 p_main;        // on both pipes, main pipe frame
    Vec3 p_work;        // same point, work frame
    Vec3 tangent_work;  // unit, direction of travel
    Vec3 normal_work;   // unit inward normal of the work pipe's surface
    Vec3 approach_work; // unit torch direction (into the material), bevel applied
};

// Arc length s(phi) of the curve, inverted numerically. Start at phi0, one full turn.
class ArcLengthTable {
  public:
    ArcLengthTable(const PipeIntersection& curve, double phi0, int samples = 8192);
    double length() const { return length_; }
    double phiAt(double s) const;
    double sAt(double phi) const;

  private:
    const PipeIntersection* curve_;
    double phi0_, dphi_;
    std::vector<double> s_; // cumulative arc length at phi0 + i * dphi
    double length_ = 0;
};

// The surfaces that meet at the cut: the main pipe's outer surface and the branch's outer
// surface (branch end) or bore (hole in the main pipe).
IntersectionSpec intersectionSpecFor(const Job& job);

// The curve parameter at which the cut starts (see CutSpec::start_phi_deg).
double startPhi(const Job& job);

class CutGeometry {
  public:
    explicit CutGeometry(const Job& job);

    const PipeIntersection& curve() const { return curve_; }
    double length() const { return table_.length(); }
    double workRadius() const { return workRadius_; }
    // Work frame expressed in the main frame (work -> main).
    const Pose& mainFromWork() const { return mainFromWork_; }
    double bevelDeg() const { return bevelDeg_; }

    // The point of the cut at arc length s in [0, length].
    CutPoint atArcLength(double s) const;
    CutPoint atPhi(double phi) const;
    // Points at equal arc length, first and last included (closed: last == first).
    std::vector<CutPoint> sampleEqualArcLength(double spacing_mm) const;
    // Points at equal steps of phi (the seed's parameterisation).
    std::vector<CutPoint> sampleByPhi(int count) const;

  private:
    PipeIntersection curve_;
    ArcLengthTable table_;
    CutTarget target_;
    double workRadius_;
    double bevelDeg_;
    double phi0_;
    Pose mainFromWork_;
    Vec3 holeCentreWork_;
};

} // namespace cutcell
