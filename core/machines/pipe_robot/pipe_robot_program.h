#pragma once
// The motion program of the seed-000 cell (pipe chuck + 5-DOF arm) for the motion engine.
//
// Axis 0 is the pipe chuck, axes 1..5 the arm joints, all rotary (rad). The reference (home)
// position is all zeros: every axis of the default DH table has 0 inside its range, and the
// arm then stands stretched out above the pipe, clear of it (checked by the builder, which
// refuses a reference outside the limits). The tip model is PipeRobot::forward of the arm
// joints; its work frame follows the chuck angle, so the engine reports the same Cartesian
// figures as simulateCut().
#include "core/engine/motion_program.h"
#include "core/job/job.h"
#include "core/machines/pipe_robot/cut_planner.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace cutcell {

// Throws std::invalid_argument when the plan is not reachable or the reference is outside
// an axis' limits (the message names the axis, the value and the limit).
std::shared_ptr<const MotionProgram> buildPipeRobotProgram(const Job& job, const CutPlan& plan,
                                                           const std::string& jobText = {});

// Tip model of the pipe robot (exposed for tests).
class PipeRobotTipModel : public TipModel {
  public:
    explicit PipeRobotTipModel(const std::array<DhRow, kAxisCount>& dh) : robot_(dh) {}
    Vec3 tip(const JointVector& q) const override;
    void tipPair(const JointVector& qa, const JointVector& qb, Vec3& a, Vec3& b) const override;
    Vec3 tipOnWork(const JointVector& q, const Vec3& tipBase) const override;
    const PipeRobot& robot() const { return robot_; }

  private:
    PipeRobot robot_;
};

} // namespace cutcell
