#pragma once
// C2 cubic spline in joint space through knots at equal time steps (seed Eq. 54-68 with the
// knot velocities solved for continuity of acceleration), clamped to zero velocity at both
// ends because the machine starts and stops at rest. Evaluation is O(1) and allocation-free,
// so the control cycle may call it.
#include "core/common/types.h"

#include <vector>

namespace cutcell {

struct JointSample {
    JointVector q = JointVector::Zero();
    JointVector qd = JointVector::Zero();
    JointVector qdd = JointVector::Zero();
};

class JointSpline {
  public:
    JointSpline() = default;
    // knots[i] is reached at t = i * dt.
    JointSpline(std::vector<JointVector> knots, double dt);

    bool empty() const { return knots_.empty(); }
    double duration() const {
        return knots_.empty() ? 0 : dt_ * static_cast<double>(knots_.size() - 1);
    }
    double dt() const { return dt_; }
    size_t knotCount() const { return knots_.size(); }
    const JointVector& knot(size_t i) const { return knots_[i]; }
    // Second derivative at knot i (for the C2 property test).
    const JointVector& knotAcceleration(size_t i) const { return m_[i]; }

    // Clamped to [0, duration]: before the start and after the end the machine is at rest.
    JointSample evaluate(double t) const;
    // Evaluate inside segment i with local time u in [0, dt] (tests of continuity).
    JointSample evaluateSegment(size_t i, double u) const;
    // The position alone, bit-identical to evaluate(t).q (the offline simulation's hot loop
    // needs no velocity or acceleration).
    JointVector position(double t) const;

  private:
    std::vector<JointVector> knots_;
    std::vector<JointVector> m_; // second derivatives at the knots
    std::vector<JointVector> c_; // knot / dt - m dt / 6: the position's linear terms
    double dt_ = 1;
};

} // namespace cutcell
