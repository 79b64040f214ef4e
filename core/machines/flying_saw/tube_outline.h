#pragma once
// The outline of a welded tube's section in the cut plane (x across, y up, centre at the pipe
// axis): a circle, or a rectangle a x b (square: a = b) with corner radius r (r = 0: sharp,
// the seed's Fig. 7). Convex and centrally symmetric, so both blades (half a turn apart) see
// the same radius and a cam table over 180 deg of the turntable serves both.
//
// Seed Eq. 14-17 (sharp rectangle, AB = a across the top, BC = b down the right side, theta
// from OA, turning A -> E -> B -> F -> C): with alpha = atan(a / b) = angle AOE and
// beta = atan(b / a) = angle BOF (alpha + beta = 90 deg), the four segments are
//   A->E  theta in [0, alpha]                 rho = b / (2 cos(alpha - theta))
//   E->B  theta in [alpha, 2 alpha]           rho = b / (2 cos(theta - alpha))
//   B->F  theta in [2 alpha, 2 alpha + beta]  rho = a / (2 cos(2 alpha + beta - theta))
//   F->C  theta in [2 alpha + beta, 180 deg]  rho = a / (2 cos(theta - 2 alpha - beta))
// and the radial feed is s = OA - rho with OA = sqrt(a^2 + b^2) / 2. With a corner radius the
// ray may meet a corner arc instead; polarRadius() handles both.
#include <Eigen/Core>

namespace cutcell {

struct TubeOutline {
    bool round = true;
    double half_width = 0;  // a / 2 (round: the radius)
    double half_height = 0; // b / 2 (round: the radius)
    double corner_radius = 0;

    static TubeOutline circle(double radius);
    static TubeOutline rectangle(double width, double height, double cornerRadius);
    // The outline moved inward by d (the tube's bore for d = wall): corner radius max(r - d, 0).
    TubeOutline inset(double d) const;

    // Distance from the centre to the outline along the direction at angle psi (rad, from +x).
    double polarRadius(double psi) const;
    // Signed distance of a point to the outline (negative inside); independent of polarRadius.
    double signedDistance(const Eigen::Vector2d& p) const;
    double maxRadius() const; // largest polarRadius (corner)
    // Direction of the seed's corner A (top left) and the segment angles alpha, beta.
    double cornerA() const;
    double alpha() const;
    double beta() const;
};

// The seed's Eq. 14-17 for a sharp rectangle a x b: the feed at turntable angle theta in
// [0, pi] measured from OA (for tests and the erratum).
double seedFeed(double a, double b, double theta);

} // namespace cutcell
