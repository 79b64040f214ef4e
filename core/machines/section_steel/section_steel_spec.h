#pragma once
// The `machine` section of a section-steel job (Job::machine_spec), read and written by
// SectionSteelModule. Cell layout (the seed gives none; see README "Section-steel cutter"):
// world x along the bar (the kept part at x < 0, the end cut through x = 0 at mid-height),
// y across, z up from the table. The 3R path arm works in the square cut plane x = 0 (joint
// axes along x, base at (0, y, z)); the 5-DOF groove arm hangs beside the bar end, its base
// frame x0 = down, y0 = -y, z0 = -x (its 2R arm in a plane parallel to the cut plane).
#include "core/job/job.h"
#include "core/machines/section_steel/section_catalogue.h"

#include <array>
#include <string>

namespace cutcell::section_steel {

inline constexpr int kPathAxes = 3;   // axes 0..2
inline constexpr int kGrooveAxes = 5; // axes 3..7
inline constexpr int kSteelAxes = kPathAxes + kGrooveAxes;

enum class GrooveType { None, V, Y, K };
const char* toString(GrooveType g); // "none", "V", "Y", "K"

// ISO 9692-1 preparation of one face kind: V = single bevel through the thickness, Y = single
// bevel with a root face, K = double bevel (from both faces of the plate) with a root face.
struct GrooveSpec {
    GrooveType type = GrooveType::None;
    double angle_deg = 30;   // bevel angle beta (torch tilt from the square cut)
    double root_face_mm = 0; // c (Y, K)
};

struct EndCutSpec {
    double mitre_vertical_deg = 0;   // about z (the cut line on the flanges turns in plan)
    double mitre_horizontal_deg = 0; // about y (the cut line on the web tilts in elevation)
    GrooveSpec flanges;              // flanges (angles: the horizontal leg)
    GrooveSpec web;                  // web (angles: the vertical leg)
    // Setup (end_cut.setup): 1 = the section as loaded (underside on the conveyor): the square
    // or mitred cut and every bevel the torch reaches. 2 = the section turned over by the
    // operator, 180 deg about its long axis (y, z -> -y, h - z; the mitres change sign in the
    // cell's frame): only the bevel that setup 1 could not cut, the underside of the bottom
    // flange (angles: horizontal leg) of a K groove on the flanges.
    int setup = 1;
};

inline constexpr int kLastSetup = 2;

// Who the piece is for, as the detailing software marked it (a DSTV header's order, drawing,
// phase and piece marks, steel grade and quantity); shown to the operator, not used by the cut.
// Absent from a job written by hand: all empty, quantity 1.
struct PieceMarks {
    std::string order, drawing, phase, mark, steel_grade;
    int quantity = 1;
    bool empty() const {
        return order.empty() && drawing.empty() && phase.empty() && mark.empty() &&
               steel_grade.empty() && quantity == 1;
    }
};

struct ArmJointLimit {
    double min_deg = -180, max_deg = 180;
};

struct SectionSteelSpec : MachineSpecOf<SectionSteelSpec> {
    SectionDims section;       // from the catalogue (designation) or user-defined
    bool user_defined = false; // written as dimensions rather than a designation
    double length_mm = 1000;   // of the bar (drawn; only its end at x = 0 is cut)
    PieceMarks piece;
    EndCutSpec cut;
    double speed_mm_s = 5;        // along the outline
    double ramp_s = 0.5;          // to and from the cutting speed
    double knot_spacing_mm = 2;   // of the joint spline along the path
    double reorient_deg_s = 45;   // torch turn at sharp corners (toes), tip at rest
    double blend_mm = 10;         // the bevel tilt ramps in and out over this length per face
    double torch_length_mm = 150; // torch body behind the tip (collision check)
    double torch_radius_mm = 12;  // torch body radius (a cone at the nozzle)
    // Where the body would hit the section the torch leans along the cut edge, in the kerf
    // (or bevel) surface, by at most this much: the cut face does not change.
    double max_lean_deg = 60;
    // Path arm: base in the cut plane, link lengths (seed: 1000, 1110, 310 mm), limits.
    double path_base_y_mm = 0, path_base_z_mm = 1800;
    std::array<double, 3> path_links_mm{1000, 1110, 310};
    std::array<ArmJointLimit, 3> path_limits{};
    // Groove arm: base position (frame as above), limits.
    double groove_base_x_mm = 120, groove_base_y_mm = 0, groove_base_z_mm = 1500;
    std::array<ArmJointLimit, 5> groove_limits{};
    // Park position of every axis (deg): the reference, and where the idle arm waits.
    std::array<double, kSteelAxes> park_deg{};
    // Simulated drives: PID (on the joint error, torque out) and joint plant per axis.
    std::array<PidGains, kSteelAxes> controller{};
    std::array<JointPlantParams, kSteelAxes> plant{};
};

SectionSteelSpec defaultSectionSteelSpec();

} // namespace cutcell::section_steel
