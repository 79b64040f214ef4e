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
//
// With leads (process.lead_in / lead_out, profile_lead.h) the program runs the whole torch path
// the G-code runs: the lead-in from the pierce point, the closed cut, the lead-out (overlap past
// the start, then the lead). One speed profile (ramps of cut.ramp_s, the cutting speed between)
// covers the whole path; every lead point, the cut's first and closing point are knots (each
// stretch between two of them gets a whole number of the equal time steps, never fewer than its
// profile time needs: the torch never runs faster than the profile), so the spline passes
// through every lead point. The torch is lit at the pierce point and dwells pierce_s = the
// pierce delay (chart or profile_cutter.pierce_s) before the path moves; the cruise window lies
// on the cut only. The torch height Z (pierce height, then down to the cut height) is NOT in the
// engine program: the machine has no Z drive, and a third, simulated axis would have to be
// carried by the rig, the module's axes, the run report and the GUI's axis views alike; the
// G-code alone writes Z (as a simulated axis). Without leads the program is the cut alone, as
// before.
#include "core/engine/motion_program.h"
#include "core/job/job.h"
#include "core/json/json.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/profile_lead.h"
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

// Where the parts of the torch path are among the program's knots (knot k at t = k dt).
struct ProfileProgramLayout {
    std::vector<size_t> lead_in_knots;  // one per ProfileLeads::lead_in point, the pierce first
    size_t cut_first_knot = 0;          // the cut's first point
    size_t cut_last_knot = 0;           // its closing point (the first point one turn later)
    std::vector<size_t> lead_out_knots; // one per ProfileLeads::lead_out point
};

// Throws std::invalid_argument naming the key, value and limit when the cut leaves the X travel.
// The first form computes the job's leads (computeProfileLeads on the job's own grid, as the
// plan); a lead problem is thrown as well.
std::shared_ptr<const MotionProgram> buildProfileCutterProgram(const Job& job,
                                                               const std::string& jobText = {});
std::shared_ptr<const MotionProgram>
buildProfileCutterProgram(const Job& job, const ProfileLeads& leads,
                          const std::string& jobText = {}, ProfileProgramLayout* layout = nullptr);

// The engine's tracking report in the profile cutter's own units: A in deg, X in mm (the shared
// report names every axis as a robot joint in deg), the torch's miss on the pipe in mm.
json::Value profileRunReportJson(const TrackingReport& report);

} // namespace cutcell
