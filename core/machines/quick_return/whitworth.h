#pragma once
// The inverted Whitworth quick-return mechanism of seed 004, Appendix B, from its loop
// equations (B.1). Crank pivot O2 at the origin, crank length r2 (angle q); the crank pin A
// slides on the rocker through O3 = (o3x, o3y) at distance r3 (rocker angle theta3); the point
// B on the rocker at r3 + AB from O3 carries the link r4 (angle theta4) to the slider on the
// vertical line x = dx at height y.
//
// Assembly branch: theta4 = 2 pi - acos(c) in (pi, 2 pi), i.e. the link hangs below B
// (sin theta4 < 0), as B.2 prints it. theta3 uses atan2 of the full vector A - O3 (B.2's
// arctan drops O3y and the quadrant; r2 sin q / sin theta3 is 0/0 at theta3 = 0, pi, so r3 is
// the length |A - O3| here).
//
// The slider's scale reads y + scale_offset (its zero is where it is mounted), so that the
// controller works in the seed's figures (top of the stroke y_min = 0.0543 m).
#include <array>
#include <string>
#include <vector>

namespace cutcell::quick_return {

struct WhitworthDims {
    double o3x = 0.085, o3y = 0; // m, rocker pivot O3
    double r2 = 0.122;           // m, crank
    double ab = 0.1215;          // m, A to B along the rocker
    double r4 = 0.366;           // m, link B to slider
    double dx = -0.061;          // m, slider line x = dx
    double scale_offset = 0.18;  // m, the scale reads y + scale_offset
};

// The seed's printed prototype (Section 6): its loop does not close for most crank angles.
WhitworthDims seedPrintedDims();

struct WhitworthPose {
    bool closes = false; // |c| <= 1: the link reaches the slider line
    double c = 0;        // cos(theta4) = (dx - o3x - (r3 + AB) cos theta3) / r4
    double r3 = 0, theta3 = 0, theta4 = 0;
    double y = 0; // slider position in the crank frame (m); scale reading = y + scale_offset
};

// B.2 with the branch above. `closes` false when |c| > 1 (theta4, y then meaningless).
WhitworthPose forwardKinematics(const WhitworthDims& d, double q);

// The joints of the mechanism at crank angle q in the crank frame (m), from B.2: the crank
// pivot O2, the crank pin A, the rocker pivot O3, the rocker's end B and the slider's point on
// the line x = dx. For drawings (the GUI's 3D view, the SVG figures). closes as the pose's.
struct WhitworthPoints {
    bool closes = false;
    std::array<double, 2> o2{}, a{}, o3{}, b{}, slider{};
};
WhitworthPoints mechanismPoints(const WhitworthDims& d, double q);

// B.3: rho = d(q, r3, theta3, theta4, y)/dq at a closed pose, corrected (row 4 divides by
// r4, not r2). Rows 4 and 5 are infinite where sin theta4 = 0 (the link horizontal).
std::array<double, 5> extendedJacobian(const WhitworthDims& d, double q, const WhitworthPose& p);
// B.3 exactly as printed (for the erratum test).
std::array<double, 5> printedJacobian(const WhitworthDims& d, double q, const WhitworthPose& p);

// A crank-angle interval [from, to] (rad, from < to, within [-pi, pi]).
struct AngleRange {
    double from = 0, to = 0;
};
// Where the loop does not close (|c| > 1), found on a fine grid refined by bisection; empty
// when the crank turns fully. *min_margin (optional): the smallest 1 - |c| over the turn.
std::vector<AngleRange> openRanges(const WhitworthDims& d, double* min_margin = nullptr);
// "q in [-3.1416, -1.7427] rad, [-1.2086, 1.2095] rad, ..." for messages.
std::string describeRanges(const std::vector<AngleRange>& ranges);

// The two singular crank angles (rho_y = 0, found where the numeric rho_y changes sign) and
// the stroke. For increasing q: the cutting stroke runs from q_top (slider highest, the seed's
// y_min) down to q_bottom (the seed's y_max); the return stroke from q_bottom back to q_top.
struct StrokeInfo {
    bool ok = false;                // the crank turns fully and exactly two sign changes were found
    double q_top = 0, q_bottom = 0; // rad in [-pi, pi)
    double y_top = 0, y_bottom = 0; // scale readings (m): y_top > y_bottom
    double stroke = 0;              // y_top - y_bottom (m), the seed's L_c
    double cut_arc = 0, return_arc = 0; // rad of crank turn (increasing q)
    double max_abs_rho_y = 0;           // m/rad over the turn
    double max_abs_rho_y_cut = 0;       // m/rad over the cutting branch (K_rho of Eq. 33)
    double min_link_margin = 0;         // smallest 1 - |c| (0 = the link goes horizontal)
};
StrokeInfo strokeInfo(const WhitworthDims& d);

// Angle wrapped into [-pi, pi).
double wrapAngle(double a);

} // namespace cutcell::quick_return
