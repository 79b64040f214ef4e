#pragma once
// The motion program of the 2-axis NC pipe profile cutter (seed 002) for the motion engine.
//
// Axis 0 = A, the pipe turning in the chuck (rotary, rad); axis 1 = X, the torch carriage
// (linear, mm); axes 2..5 are absent. The cut of computeProfileCut() is followed at the cutting
// speed on the developed pipe surface (ds = sqrt(dX^2 + (R_w dA)^2), the seed's constant
// cutting rate) with the cosine start/stop ramps of cut.ramp_s (SpeedProfile, as the robot),
// sampled at equal time steps about cut.knot_spacing_mm apart for the C2 joint spline.
//
// The tip model gives the torch tip ON THE PIPE (work frame: pipe axis = z, A = 0 puts the top
// generatrix under the torch): (R_w sin A, R_w cos A, X). The Cartesian error of the engine is
// then the torch's miss on the pipe surface, |e| ~ sqrt(dX^2 + (R_w dA)^2).
#include "core/engine/motion_program.h"
#include "core/job/job.h"
#include "core/json/json.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/sim/tracking_stats.h"

#include <memory>
#include <string>

namespace cutcell {

class ProfileCutterTipModel : public TipModel {
  public:
    explicit ProfileCutterTipModel(double workRadius) : r_(workRadius) {}
    Vec3 tip(const JointVector& q) const override;

  private:
    double r_;
};

// The cut resampled by developed length (closed polyline of a fine grid): A (deg) and X (mm) at
// surface distance s from the start, s in [0, length()].
class DevelopedPath {
  public:
    DevelopedPath(const ProfileCut& cut);
    double length() const { return s_.back(); }
    // Linear interpolation between the grid points; s is clamped to [0, length()].
    void at(double s, double* aDeg, double* xMm) const;

  private:
    std::vector<double> s_, a_, x_;
};

// Throws std::invalid_argument naming the key, value and limit when the cut leaves the X travel.
std::shared_ptr<const MotionProgram> buildProfileCutterProgram(const Job& job,
                                                               const std::string& jobText = {});

// The engine's tracking report in the profile cutter's own units: A in deg, X in mm (the shared
// report names every axis as a robot joint in deg), the torch's miss on the pipe in mm.
json::Value profileRunReportJson(const TrackingReport& report);

} // namespace cutcell
