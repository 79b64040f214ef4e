#pragma once
// Kerf compensation on a pipe (issue 24), the geometry only: no machine, no job key.
//
// The torch burns a slot of width k (the kerf) centred on its axis. The theoretical edge is
// where the kept part must end, so the torch centre runs k/2 off the edge toward the scrap
// side and the slot's near face passes through the edge.
//
// Definitions, at a point p of the theoretical edge on the pipe's outer surface (a cylinder):
// - t: the edge's unit tangent; d: the torch axis (into the material, bevel applied).
// - The cut surface at p is the plane through p spanned by t and d (the surface the torch axis
//   sweeps along the edge, to first order). Its unit normal n = t x d / |t x d|, turned toward
//   the scrap side; m = n x t is the torch axis with its lean along t removed (m = d when the
//   torch is square to the travel, as CutGeometry makes it).
// - "k/2 across the cut surface" is measured along n, perpendicular to the cut surface: the
//   torch centre q is the point of the pipe's outer surface with (q - p) . n = k/2 that lies in
//   the plane through p normal to t (the edge's cross-section). So q = p + k/2 n + s m, with s
//   the root of |q - axis| = radius nearest 0 (closed form). Why this choice: the torch axis
//   through q (direction d, d . n = 0) then lies entirely in the plane k/2 off the cut surface,
//   so the slot's near face is the cut surface itself at every depth, not only on the outer
//   skin; and staying in the cross-section plane adds no shift along the travel (arc length
//   and timing are the edge's). Along the surface q is |q - p| ~ (k/2) / cos(angle between
//   the surface and n) from p: with the torch square to the travel that angle is the bevel,
//   so a 30 deg bevel moves the torch 1.155 * k/2 along the surface.
// - The inverse (torch centre -> edge) is the same construction with -k/2, using the tangent
//   and torch axis stored with the torch point (the edge's: compensation keeps them).
//
// Limits (refused with an Outcome naming value, unit and limit):
// - k finite and >= 0 mm;
// - k/2 <= 0.1 x the pipe radius: the construction treats the cut surface as its tangent plane
//   at p; over 0.1 R the pipe's own curvature bends the skin (k/2)^2 / 2R = 0.05 k/2 away from
//   it (a 2 mm kerf needs R >= 10 mm, the cut charts' widest, 10 mm, R >= 50 mm);
// - on a path, k/2 <= 0.5 x the edge's radius of curvature toward the scrap side (curvature
//   vector . n, from neighbouring points): at 1.0 the torch path would collapse to a cusp, at
//   0.5 its radius of curvature is still half the edge's;
// - the torch axis at least 10 deg from the tangent (else no cut surface), and the cut surface
//   at least 1 deg from the pipe surface (else it has no sides on the pipe: a torch lying flat).
#include "core/common/outcome.h"
#include "core/common/types.h"
#include "core/geometry/cut_path.h"
#include "core/job/job.h"

#include <vector>

namespace cutcell {

// A pipe's outer surface: the cylinder of `radius_mm` about the line through axis_point with
// direction axis_dir (unit).
struct PipeSurface {
    Vec3 axis_point = Vec3::Zero();
    Vec3 axis_dir = Vec3::UnitZ();
    double radius_mm = 0;
};

// Which side of the edge is scrap: +1 left of the travel, -1 right, seen from outside the pipe
// (left = outward normal x tangent). One side for a whole path: the hole's inside, or the branch
// end's off-cut, never changes sides along the cut. (A local hint such as "toward the other
// pipe's axis" says it only where the two pipes are not nearly tangent: at |e| + r close to R
// it lies within a degree of the cut surface, so scrapSideFor() takes it over the whole path.)
enum class ScrapSide : int { Left = +1, Right = -1 };

struct KerfPoint {
    Outcome outcome;
    Vec3 point = Vec3::Zero();   // torch centre (offset) or edge (inverse)
    Vec3 across = Vec3::Zero();  // n: unit normal of the cut surface, toward the scrap side
    double along_surface_mm = 0; // |q - p|
};

// Torch centre for the edge point p (on `pipe`) with tangent t and torch axis d.
KerfPoint offsetEdgePoint(const PipeSurface& pipe, const Vec3& p, const Vec3& t, const Vec3& d,
                          ScrapSide scrap, double kerf_mm);
// Edge point for the torch centre q (on `pipe`) with the stored tangent t and torch axis d.
KerfPoint edgeFromTorchPoint(const PipeSurface& pipe, const Vec3& q, const Vec3& t, const Vec3& d,
                             ScrapSide scrap, double kerf_mm);

// A whole cut path in the work frame (CutGeometry's points): the work pipe is the cylinder of
// radius work_radius_mm about the work z axis; scrap is given in the work frame.
struct KerfPathSpec {
    double work_radius_mm = 0;
    Pose main_from_work = Pose::Identity();
    ScrapSide scrap = ScrapSide::Left;
    bool closed = true; // closed: the last point repeats the first (sampleEqualArcLength)
};
struct KerfPath {
    Outcome outcome;
    std::vector<CutPoint> points; // p_work / p_main moved; phi, s, tangent, normal, torch kept
    double max_stretch = 0;       // largest |q - p| / (k/2): the bevel's 1/cos
};
// Torch-centre path from the theoretical edge; refuses with the first point that fails.
KerfPath offsetCutPath(const KerfPathSpec& spec, const std::vector<CutPoint>& edge, double kerf_mm);
// One point of such a path moved to the torch centre (p_work, p_main; the rest kept), without
// the path's curvature check (offsetCutPath on the sampled edge does that once).
KerfPoint offsetCutPoint(const KerfPathSpec& spec, CutPoint& point, double kerf_mm);
// Edge from a torch-centre path made by offsetCutPath.
KerfPath edgeFromTorchPath(const KerfPathSpec& spec, const std::vector<CutPoint>& torch,
                           double kerf_mm);

// Kerf on a prism (the section steel's end cut): a surface made of straight lines parallel to
// the unit vector `lines` - a section's faces, root fillets, toe radii and corners all run along
// the bar. The cut surface at the edge point p is again the plane spanned by the edge's tangent t
// and the torch axis d, its unit normal n turned toward `toward_scrap`. The torch centre moves
// along the prism's line through p: q = p + (k/2) / (n . lines) lines, so that
// - q lies on the prism exactly, whatever its cross-section there (flat face, fillet of any
//   radius, the corner the torch turns about): no radius limit, no first-order step;
// - (q - p) . n = k/2, and the torch axis through q (d . n = 0) lies in the plane k/2 off the cut
//   surface at every depth: where the cut surface is a plane (a square or mitred cut, a bevel of
//   constant angle) the slot's near face is that plane.
// Along the prism |q - p| = (k/2) / (n . lines): for a square cut k/2, for a bevel beta on a
// square end (k/2) / cos(beta), the "bevel taken into account".
// The move has a component along the edge where the cut surface is not square to the lines (a
// mitre): it stays in the offset plane, so a planar pass stays planar (its arm's plane moves by
// (k/2) / (m . lines) along the lines, m the plane's normal).
// Limits (refused with an Outcome naming value, unit and limit): k finite and >= 0 mm; the torch
// axis at least 10 deg from the tangent (as on a pipe); the cut surface's normal within 80 deg of
// the lines (n . lines >= cos 80 deg: else the torch would run more than 2.9 k along the bar
// for k/2 across, and the lines nearly lie in the cut surface); the cut surface at least 1 deg
// from `toward_scrap`'s normal plane (else it has no scrap side).
KerfPoint offsetOnPrism(const Vec3& p, const Vec3& t, const Vec3& d, const Vec3& lines,
                        const Vec3& toward_scrap, double kerf_mm);
// Edge point for the torch centre q made by offsetOnPrism, with the same t, d, lines and side.
KerfPoint edgeOnPrism(const Vec3& q, const Vec3& t, const Vec3& d, const Vec3& lines,
                      const Vec3& toward_scrap, double kerf_mm);

// The spec for a job's cut. Scrap is what lies inside the other pipe (hole: inside the branch
// bore; branch end: the off-cut inside the main pipe): the side toward the other pipe's axis,
// summed over the cut so that near-tangent stretches do not decide it.
KerfPathSpec kerfPathSpecFor(const Job& job, const CutGeometry& geometry);

} // namespace cutcell
