#pragma once
// The intersection of two cylinders (seed 000 Eq. 1-8, seed 002 Eq. 1-4), in the MAIN PIPE
// FRAME: main axis along z (x^2 + y^2 = R^2); the branch axis lies in the plane x = e,
// passes through (e, 0, 0) and is tilted by the angle a from z about the x axis, with
// direction b = (0, sin a, cos a). A branch point is
//   (e + r sin(phi), 0, 0) + r cos(phi) * (0, cos a, -sin a) + t * b,
// and the side +1 takes the half of the main pipe with y > 0 (the seed's "+" root).
// The formulas hold for any angle in (0, 180) deg; jobs limit the main/branch angle to (0, 90],
// the profile cutter also uses (90, 180) for crossings of two branches (core/machines/).
#include "core/common/types.h"

namespace cutcell {

struct IntersectionSpec {
    double main_radius_mm = 0;   // R (the main pipe surface used)
    double branch_radius_mm = 0; // r (the branch pipe surface used)
    double angle_deg = 90;       // angle between the axes, (0, 90]
    double eccentricity_mm = 0;  // e, with |e| + r <= R
    int side = +1;               // +1: y >= 0 half of the main pipe, -1: y <= 0
};

class PipeIntersection {
  public:
    explicit PipeIntersection(const IntersectionSpec& spec);

    const IntersectionSpec& spec() const { return spec_; }
    Vec3 point(double phi) const;
    // dP/dphi, analytic.
    Vec3 derivative(double phi) const;
    // Axial coordinate t of the point along the branch axis (from (e, 0, 0)).
    double branchAxial(double phi) const;
    // Whether the branch's generatrix at phi meets the main cylinder at all (|e + r sin phi| <= R);
    // always true when |e| + r <= R. point() clamps where it does not.
    bool generatrixMeetsMain(double phi) const;

    Vec3 branchOrigin() const { return {spec_.eccentricity_mm, 0, 0}; }
    Vec3 branchAxis() const { return b_; }
    // Unit vector of the branch frame's y axis (the seed's R2 cos(phi) direction).
    Vec3 branchY() const { return n_; }

    // Distance of a point from each cylinder surface (property checks, diagnostics).
    double mainSurfaceDistance(const Vec3& p) const;
    double branchSurfaceDistance(const Vec3& p) const;

  private:
    IntersectionSpec spec_;
    double sa_, ca_;
    Vec3 b_, n_;
};

} // namespace cutcell
