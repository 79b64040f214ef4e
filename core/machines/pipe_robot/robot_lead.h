#pragma once
// Lead-in / lead-out and the pierce of the pipe robot's closed cut (issue 24), the robot's
// counterpart of the profile cutter's profile_lead.h, on the work pipe's developed surface
// (axial z, u = R phi of the work frame: the cylinder rolled flat, so straight lines there are
// the cylinder's geodesics).
//
//  - lead-in (process.lead_in): the torch pierces on the scrap side (inside the hole on the
//    main pipe, beyond the branch end on the branch) and runs onto the torch path's start:
//    "line" = straight, square to the cut, length_mm long; "arc" = a quarter circle of arc
//    length length_mm (radius 2 L / pi) joining the cut tangentially.
//  - lead-out (process.lead_out): after the closed cut the torch runs on along the cut for
//    overlap_mm past the start, then leaves to the scrap side by a line or a quarter arc.
//  - the torch path is the kerf-compensated one (core/process/kerf_offset.h: the torch centre
//    k/2 off the edge toward the scrap); every lead point lies on the work pipe's nominal
//    surface and on the scrap side, at least k/2 from the part's edge. A lead too long for the
//    cut (it would reach the part's edge across the hole) is refused with the longest length
//    that fits.
//  - the pierce: the planner's tool point lies on the nominal surface with the torch at the
//    cut height (torch_height.h: "the planned path follows the nominal surface at the cut
//    height"), so the torch tip stands cut_height above its tool point. At the pierce the tool
//    point stands pierce_height - cut_height above the pierce point along the torch axis (the
//    tip at pierce_height over the surface); after the pierce delay it comes down along the
//    axis to the surface (the tip at the cut height) and the lead-in starts.
//  - the torch axis along a lead: the cut's axis at the point the lead joins (lead-in: the
//    cut's start; lead-out: where it leaves the cut), carried round the pipe's axis with the
//    surface (turned about the work z axis by the lead point's phi minus the joint's), so it
//    keeps the joint's angles to the local surface; the pierce and the descent use the
//    pierce point's. Why not the plain surface normal: the axis is then continuous at the
//    joint (on the hole the cut's axis is the branch axis, tens of degrees off the main pipe's
//    normal: a normal-following lead would swing the wrist there at full speed). Why not the
//    joint's axis held fixed in the work frame: on the rotating method the chuck turns each
//    lead point to the top, and a fixed axis would then lean by the lead's turn round the
//    pipe (a 40 mm lead across a DN100 hole: 41 deg, past the 5-DOF arm's tilt limit); carried
//    with the surface it stands over every lead point as it stands over the joint.
//
// No lead keys: nothing of this is used and the plan is the one without leads, bit for bit.
#include "core/geometry/cut_path.h"
#include "core/job/issue_checker.h"
#include "core/job/job.h"
#include "core/process/kerf_offset.h"
#include "core/process/process_spec_data.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cutcell {

// Which part of the robot's program a planned point belongs to.
enum class PathPart : std::uint8_t { Cut, Descent, LeadIn, Overlap, LeadOut };
const char* toString(PathPart p);

// What the job asks for, resolved against the cut chart (no geometry).
struct RobotLeadSettings {
    bool used = false;   // a lead-in, a lead-out or an overlap is asked for
    bool pierce = false; // a lead-in or a lead-out: pierce at the pierce height, then descend
    LeadSpec in, out;
    double pierce_height_mm = 0, cut_height_mm = 0; // torch tip over the surface
    double pierce_delay_s = 0;                      // the chart's pierce delay, else 0
    std::string problem, problem_key;               // cannot be planned: why, and the key
};
RobotLeadSettings robotLeadSettings(const Job& job);

// The job's lead issues the validation reports (the heights come from checkProcess): a pierce
// height below the cut height.
void checkRobotLeads(IssueChecker& c, const Job& job);

// The torch's whole way of one cut with its leads: the descent at the pierce, then the travel
// (lead-in, cut, overlap, lead-out) on the work pipe's surface. Points are CutPoints of the work
// frame as the planner uses them: p_work the tool point, approach_work the torch axis.
class RobotLeadPath {
  public:
    // geo: the cut; kerf, kerf_mm: as the planner compensates (kerf_mm 0: the torch on the edge;
    // kerf.scrap says the scrap side either way).
    RobotLeadPath(const Job& job, const CutGeometry& geo, const KerfPathSpec& kerf, double kerf_mm);

    const RobotLeadSettings& settings() const { return settings_; }
    bool ok() const { return problem_.empty(); }
    const std::string& problem() const { return problem_; }
    const std::string& problemKey() const { return problemKey_; }

    double descentMm() const { return descent_mm_; } // pierce - cut height (0: no descent)
    double leadInMm() const { return lead_in_mm_; }
    double cutMm() const { return cut_mm_; }
    double overlapMm() const { return overlap_mm_; }
    double leadOutMm() const { return lead_out_mm_; }
    double travelMm() const { return lead_in_mm_ + cut_mm_ + overlap_mm_ + lead_out_mm_; }

    // d in [0, descentMm()]: the tool point from the pierce height (d = 0) down along the torch
    // axis to the pierce point on the surface.
    CutPoint descentAt(double d) const;
    // d in [0, travelMm()]: the tool point along the travel, and which part it is in.
    CutPoint travelAt(double d, PathPart* part = nullptr) const;
    // The torch path (compensated) at the cut's arc length s (any s: taken modulo the length).
    CutPoint torchAt(double s) const;

    // The test on the part's edge (developed, on the work pipe): whether a work-frame point of
    // the work pipe's surface lies on the scrap side, and its distance along the surface to the
    // edge (the edge polyline sampled every 0.2 mm or finer).
    bool onScrapSide(const Vec3& p_work) const;
    double distanceToEdge(const Vec3& p_work) const;

  private:
    struct D {
        double z, u;
    };
    D developed(const Vec3& p_work) const;
    Vec3 work(D d) const;
    D tangentAt(double s) const;
    D scrapNormal(D t) const;
    D leadInAt(double sigma, double L, D* tangent) const;
    D leadOutAt(double sigma, double L, D* tangent) const;
    CutPoint surfacePoint(D d, D tangent, const CutPoint& like, double s, const Vec3& axis) const;
    bool clear(const std::vector<D>& pts) const;
    double distanceDev(D d) const;
    bool scrapDev(D d) const;

    const CutGeometry* geo_;
    KerfPathSpec kerf_;
    double kerf_mm_ = 0;
    RobotLeadSettings settings_;
    std::string problem_, problemKey_;
    double R_ = 0, phi0_ = 0;
    double descent_mm_ = 0, lead_in_mm_ = 0, cut_mm_ = 0, overlap_mm_ = 0, lead_out_mm_ = 0;
    CutPoint start_, leave_; // the torch path at s = 0 and where the lead-out leaves it
    D p0_{}, t0_{}, n0_{};   // developed start, its tangent and scrap normal
    D e_{}, te_{}, ne_{};    // developed leaving point, its tangent and scrap normal
    std::vector<D> edge_;    // the part's edge, developed, unwrapped along the curve
    bool wraps_ = false;     // the edge goes once round the work pipe (the branch end)
    bool scrapUp_ = false;   // wraps_: the scrap lies toward larger z
};

} // namespace cutcell
