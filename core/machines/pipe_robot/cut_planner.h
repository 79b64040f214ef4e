#pragma once
// Plans a cut of the seed-000 cell: the cut point moves along the intersection curve at the
// cutting speed (arc length on the pipe surface; smooth cosine ramps of cut.ramp_s at both
// ends), each knot is turned into a torch pose and solved by the IK, and a C2 joint spline
// runs through the knots.
//
//  - static_pipe:   the chuck holds cut.static_chuck_deg; the arm follows the curve.
//  - rotating_pipe: the chuck turns so that the cut point is always at the top of the work
//                   pipe (Y0 = 0, Z0 = work radius); the torch moves on that straight line.
//
// A 5-DOF arm keeps its torch in the plane of joint 1. The planner tilts the desired torch
// axis into that plane (its nearest direction there) and records the tilt as the direction
// deviation; above cut.max_direction_deviation_deg the point is not reachable.
#include "core/common/types.h"
#include "core/geometry/cut_path.h"
#include "core/job/job.h"
#include "core/machine/plan_options.h"
#include "core/machines/pipe_robot/pipe_robot.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "core/machines/pipe_robot/robot_lead.h"
#include "core/trajectory/joint_spline.h"
#include "core/trajectory/speed_profile.h"

#include <memory>
#include <string>
#include <vector>

namespace cutcell {

struct PlannedPoint {
    double t_s = 0;
    CutPoint cut;             // on the pipes (main and work frames)
    double chuck_rad = 0;     // axis 0
    Vec3 tip_base;            // torch tip in the robot base frame {0}
    Vec3 approach_base;       // torch axis actually commanded (in the plane of joint 1)
    double deviation_deg = 0; // angle between the desired and the commanded torch axis
    IkResult ik;
    JointVector q = JointVector::Zero(); // axis 0 = chuck, 1..5 = arm
    PathPart part = PathPart::Cut;       // with leads: the descent, a lead, the overlap
};

struct CutPlan {
    CutMethod method = CutMethod::RotatingPipe;
    double length_mm = 0;
    double cut_time_s = 0; // from start to stop, ramps included (with leads: the whole program)
    double knot_dt_s = 0;
    std::vector<PlannedPoint> knots;
    JointSpline spline;
    bool reachable = false;
    int first_bad = -1;  // index into knots of the first unreachable point
    std::string problem; // one sentence naming the point, the joint and the limit
    double max_deviation_deg = 0;
    bool cancelled = false;
    // Kerf compensation (process section): the torch centre runs kerf_mm / 2 off the theoretical
    // edge toward the scrap side (core/process/kerf_offset.h); 0 = the torch on the edge.
    double kerf_mm = 0;
    // Path-time window of the cut at constant speed (ramps and leads excluded).
    double cruise_from_s = 0, cruise_to_s = -1;
    // Leads (robot_lead.h; process.lead_in / lead_out): the knots run from the pierce at the
    // pierce height down to the surface, along the lead-in, the cut, the overlap and the
    // lead-out; the torch is lit at the first knot and pierces for pierce_delay_s there.
    bool leads = false;
    double descent_mm = 0, lead_in_mm = 0, overlap_mm = 0, lead_out_mm = 0;
    double pierce_height_mm = 0, cut_height_mm = 0, pierce_delay_s = 0;
    std::string problem_key; // the job key the problem is about, where one is
};

CutPlan planCut(const Job& job, const PlanOptions& options = {});

} // namespace cutcell
