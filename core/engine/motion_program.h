#pragma once
// What the engine runs: a joint trajectory for up to six axes with the cut's length, and a
// model that turns joint values into a torch tip position for the Cartesian error. Built by a
// machine (the pipe robot, the 2-axis profile cutter) from a job; the engine knows no machine.
#include "core/common/types.h"
#include "core/trajectory/joint_spline.h"

#include <array>
#include <memory>
#include <string>

namespace cutcell {

// Torch tip position (mm) for joint values; used for the Cartesian tracking error.
class TipModel {
  public:
    virtual ~TipModel() = default;
    virtual Vec3 tip(const JointVector& q) const = 0;
};

struct MotionProgram {
    std::string machine;                // "pipe_robot_6axis", "profile_cutter_2axis"
    int axis_count = kAxisCount;        // axes 0..axis_count-1 are driven
    std::array<std::string, kAxisCount> axis_names{};
    std::array<bool, kAxisCount> axis_linear{}; // mm instead of rad
    JointSpline spline;                 // t = 0 .. cut_time_s, at rest at both ends
    double cut_time_s = 0;
    double length_mm = 0;
    size_t point_count = 0;             // knots along the cut (progress: current point / total)
    JointVector reference = JointVector::Zero(); // home position of every axis
    std::shared_ptr<const TipModel> tip_model; // may be null
};

} // namespace cutcell
