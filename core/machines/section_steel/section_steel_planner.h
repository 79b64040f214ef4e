#pragma once
// Plans an end cut of the section-steel cell: the passes of EndCut, the inverse kinematics of
// the arm that cuts each pass at every point (the other arm waits at its park position), the
// joint limits and the torch-body collision per point, and the 8-axis joint spline.
#include "core/machines/section_steel/end_cut_path.h"
#include "core/machines/section_steel/groove_arm.h"
#include "core/machines/section_steel/path_arm.h"
#include "core/machines/section_steel/section_lead.h"
#include "core/trajectory/joint_spline.h"

#include <string>
#include <vector>

namespace cutcell::section_steel {

// The two arms placed in the cell (frames as in section_steel_spec.h).
struct SteelCell {
    explicit SteelCell(const SectionSteelSpec& spec);
    // For a cut with kerf compensation (section_kerf.h): the mitre frame, both arms on it, stands
    // frame_shift_mm = (k/2) / (x . m) along the bar toward the off-cut, so that the path arm's
    // plane is the square / mitre pass's, k/2 off the cut plane.
    SteelCell(const SectionSteelSpec& spec, double kerf_mm);
    double frame_shift_mm = 0; // along world x
    PathArm path;
    GrooveArm groove;
    // Both arms stand on a mitre frame that turns the square layout about the section's
    // centre (0, 0, h/2) so that its x axis is the cut plane's normal (as a mitre band saw's
    // head turns and tilts): the identity for a square cut.
    Pose groove_base = Pose::Identity();     // world <- groove arm base
    double path_base_y = 0, path_base_z = 0; // in the square layout
    // world <- path arm plane: x = the joint axes (the cut plane's normal), y and z span the
    // cut plane. Square: the world axes, base at (0, base_y, base_z).
    Pose path_frame = Pose::Identity();
    // Torch tip and direction (world) of the arms at the joints (rad).
    void pathTorch(const std::array<double, 3>& q, Vec3& p, Vec3& t) const;
    // The path arm's planar pose of a world target; false when it is not in the arm's plane.
    bool pathPlanar(const Vec3& p, const Vec3& t, PlanarPose& out) const;
    void grooveTorch(const Q5& q, Vec3& p, Vec3& t) const;
};

struct KnotInfo {
    int pass = -1; // -1: transition between passes
    size_t sample = 0;
};

struct SteelPlan {
    bool ok = false;
    std::string problem; // the first point that fails: point, face, arm, joint, limit
    size_t failed_points = 0;
    std::vector<CutPass> passes;
    std::vector<JointVector> knots; // rad, axes 0..2 path arm, 3..7 groove arm
    std::vector<KnotInfo> info;
    JointSpline spline;
    double dt = 0, cut_time_s = 0, length_mm = 0;
    double max_torch_error_mm = 0; // FK of the chosen joints against the targets
    // Kerf compensation (the job's process section; section_kerf.h): the passes' targets are the
    // torch centres, k/2 across the cut surface toward the scrap side (TorchTarget::edge_p keeps
    // the theoretical edge), the arms' frame moved by frame_shift_mm (SteelCell). 0: on the edge.
    double kerf_mm = 0;
    double frame_shift_mm = 0;
    // Why the kerf could not be compensated ("" when it was, or k = 0): the plan is then made on
    // the theoretical edge (kerf_mm = 0) for the view, and refused (ok false, problem = this).
    std::string kerf_problem;
    // Leads (section_lead.h): the square pass's samples then begin with the pierce and the
    // lead-in and end with the lead-out (TorchTarget::lead). lead_problem: a lead too long for the
    // cell (key lead_key, with the longest that fits); the plan is then made without the leads
    // (for the view) and refused.
    bool leads_added = false;
    SteelLeadSamples leads;
    std::string lead_problem, lead_key;
};

SteelPlan planEndCut(const SectionSteelSpec& spec);
// With the kerf `kerf_mm` compensated (0: as planEndCut(spec), bit for bit).
SteelPlan planEndCut(const SectionSteelSpec& spec, double kerf_mm);
// With the leads `leads` too (none: as planEndCut(spec, kerf_mm), bit for bit).
SteelPlan planEndCut(const SectionSteelSpec& spec, double kerf_mm, const SteelLeadSpec& leads);

// Why the path arm cannot cut at the target tt of the square pass ("" when it can): out of its
// plane, no IK solution inside the limits, the torch body hitting the section.
std::string steelPathPointProblem(const SteelCell& cell, const SectionSteelSpec& spec,
                                  const EndCut& cut, const TorchTarget& tt);

// A description of the point for messages: "point 37 of pass groove (top flange, upper face,
// s = 120.0 mm)".
std::string describePoint(const EndCut& cut, const CutPass& pass, size_t k);

} // namespace cutcell::section_steel
