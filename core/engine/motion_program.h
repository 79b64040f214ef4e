#pragma once
// What the engine runs: a joint trajectory for up to six axes with the cut's length, and a
// model that turns joint values into a torch tip position for the Cartesian error. Built by a
// machine (the pipe robot, the 2-axis profile cutter) from a job; the engine knows no machine.
#include "core/common/types.h"
#include "core/kinematics/tip_model.h"
#include "core/trajectory/joint_spline.h"

#include <array>
#include <memory>
#include <string>

namespace cutcell {

struct MotionProgram {
    std::string machine;         // the id of the machine module that built it
    std::string method;          // how the machine cuts (e.g. "rotating_pipe"), for reports
    int axis_count = kAxisCount; // axes 0..axis_count-1 are driven
    std::array<std::string, kAxisCount> axis_names{};
    std::array<bool, kAxisCount> axis_linear{}; // mm instead of rad
    JointSpline spline;                         // t = 0 .. cut_time_s, at rest at both ends
    double cut_time_s = 0;
    double length_mm = 0;
    size_t point_count = 0; // knots along the cut (progress: current point / total)
    JointVector reference = JointVector::Zero(); // home position of every axis
    std::shared_ptr<const TipModel> tip_model;   // may be null
    // Operating range of every axis (rad or mm); jogs and the reference are checked against it.
    JointVector min_position = JointVector::Constant(-1e9);
    JointVector max_position = JointVector::Constant(1e9);
    // The run lasts at least this long from the first cut sample (the drives keep being
    // tracked after the path's end until then), so its figures cover the same span as the
    // offline simulation (sim.duration_s).
    double min_run_s = 0;
    // After the arc is established at the first cut point the torch dwells this long before
    // the path moves (the G-code's G4 pierce dwell); 0 = move at once.
    double pierce_s = 0;
    // Path-time window of constant cutting speed (the report's "cruise" figures); empty if to <
    // from.
    double cruise_from_s = 0;
    double cruise_to_s = -1;
    std::string name; // the job's name, for the run log
    std::string
        source_text; // the job file (JSON) the program was built from: job.json of the run log
};

} // namespace cutcell
