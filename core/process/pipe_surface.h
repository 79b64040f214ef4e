#pragma once
// A real pipe's outer surface in the chuck (issue 24, torch height control): not the perfect
// cylinder the planner cuts on, but an out-of-round pipe mounted off-centre. The geometry only:
// no machine, no job key. (kerf_offset.h's PipeSurface is the nominal cylinder; this is the
// actual one, hence the other name.)
//
// Frame: the work frame of core/geometry/cut_path.h, which turns with the chuck: z is the
// rotation (chuck) axis, z = 0 the middle of the cut. A pipe-frame angle phi is measured about
// z from the work frame's x axis. A point that is at phi on the pipe is seen by a fixed torch
// at the machine angle theta = phi + chuck angle (the chuck turns the pipe by +chuck about z).
//
// Defects (PipeDefects):
// - Ovality, the standard out-of-roundness O = D_max - D_min (the difference of the largest and
//   smallest outside diameter of one cross-section, as pipe standards measure it with a
//   caliper). The cross-section is an ellipse of semi-axes a = R + O/4 (at major_axis_deg) and
//   b = R - O/4, so the nominal diameter 2R is the mean of D_max and D_min. In radius that is
//   only +-O/4: a 2 mm ovality moves the surface under a radial torch by +-0.5 mm.
// - Run-out from an eccentric chuck mount: the pipe's own axis is offset by e from the rotation
//   axis, toward runout_deg in the pipe frame. A fixed torch then sees the surface rise and
//   fall by +-e per turn (total indicator reading 2e).
// - Taper: the diameter changes linearly along z by taper_mm_per_m (mm per metre). A bow is not
//   modelled separately: near a cut (tens of mm long) a bowed pipe is a pipe whose axis is
//   offset at the cut, i.e. a run-out; set e to the bow's offset at the cut.
//
// Limits (checkPipeDefects, refused with a message naming the field, value, unit and limit):
// R > 0; 0 <= O <= 10 % of the nominal diameter; 0 <= e <= R / 10; |taper| <= 20 mm/m; the
// angles finite. With these the rotation axis lies well inside the section (b - e >= 0.85 R),
// so the surface seen from the rotation axis is single-valued in every direction.
//
// Everything here after the check is allocation-free (the engine cycle may call it).
#include "core/common/outcome.h"
#include "core/common/types.h"

namespace cutcell {

struct PipeDefects {
    double radius_mm = 0;      // nominal outer radius R
    double ovality_mm = 0;     // O = D_max - D_min
    double major_axis_deg = 0; // direction of D_max in the pipe frame
    double runout_mm = 0;      // e: pipe axis offset from the rotation axis
    double runout_deg = 0;     // its direction in the pipe frame
    double taper_mm_per_m = 0; // change of the diameter per metre along +z
};

// Ok, or the first bad field (message: field, value, unit, limit).
Outcome checkPipeDefects(const PipeDefects& d);

// Where a line from a point meets the actual surface.
struct SurfaceHit {
    bool ok = false; // false: the line grazes the surface (too far off its normal) or no
                     // crossing was found near the point
    double s_mm = 0; // signed distance along the unit direction to the actual surface
    Vec3 point = Vec3::Zero();
    int iterations = 0; // Newton steps taken
};

class ActualPipeSurface {
  public:
    // Lines more than this far from the surface normal are not intersected (ill-conditioned).
    static constexpr double kMaxOffNormalDeg = 80;

    // The defects must pass checkPipeDefects (else std::invalid_argument with its message).
    explicit ActualPipeSurface(const PipeDefects& d);
    const PipeDefects& defects() const { return d_; }

    // Distance of the actual surface from the rotation axis at axial position z, in the
    // direction phi of the pipe frame. A perfect pipe (O = e = taper = 0) gives R exactly.
    double radiusAt(double z_mm, double phi_rad) const;
    // The same seen by a fixed torch at machine angle theta with the chuck at chuck_rad.
    double radiusUnderTool(double z_mm, double theta_rad, double chuck_rad) const {
        return radiusAt(z_mm, theta_rad - chuck_rad);
    }

    // From a point (pipe frame; normally on the nominal cylinder) along the unit direction d
    // (the torch axis, pointing into the material) to the actual surface: s > 0 when the
    // actual surface lies further along d than the point (the pipe is smaller there: a torch
    // set for the nominal surface stands too high by s). Safeguarded Newton on the section's
    // level function, at most 40 steps (6 at most in the tests); s to well within 1e-9 mm.
    SurfaceHit alongLine(const Vec3& p, const Vec3& d) const;

    // Signed level of a point (pipe frame): ~ its distance from the actual surface in mm
    // (exact on the surface and to first order near it), > 0 outside the pipe.
    double level(const Vec3& p) const;

  private:
    // Semi-axes of the section at z.
    double semiMajor(double z) const { return radius0_ + taperPerMm_ * z + 0.25 * d_.ovality_mm; }
    double semiMinor(double z) const { return radius0_ + taperPerMm_ * z - 0.25 * d_.ovality_mm; }
    // Level and its gradient (pipe frame).
    double levelAndGradient(const Vec3& p, Vec3* grad) const;

    PipeDefects d_;
    double radius0_ = 0;
    double taperPerMm_ = 0;      // radius change per mm of z
    double cMaj_ = 1, sMaj_ = 0; // major axis direction
    double cx_ = 0, cy_ = 0;     // pipe centre (run-out offset)
    bool perfect_ = true;        // no defect at all: the exact cylinder
};

} // namespace cutcell
