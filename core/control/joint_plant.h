#pragma once
// Joint model: J q'' + b q' = u, with u = clamp(command, +-torque_limit). Integrated exactly
// over one period for a torque held constant (zero-order hold). Real-time safe.
#include "core/job/job.h"

namespace cutcell {

class JointPlant {
  public:
    JointPlant() = default;
    JointPlant(const JointPlantParams& p, double period_s) { configure(p, period_s); }

    void configure(const JointPlantParams& p, double period_s);
    void setState(double position, double velocity) {
        q_ = position;
        v_ = velocity;
    }
    // Applies the torque command for one period; returns the torque actually applied.
    double step(double torqueCommand);

    double position() const { return q_; }
    double velocity() const { return v_; }
    double torqueLimit() const { return limit_; }
    // The exact discretisation: v+ = av v + bv u, q+ = q + aq v + bq u.
    struct Coefficients {
        double av, bv, aq, bq;
    };
    Coefficients coefficients() const { return {av_, bv_, aq_, bq_}; }

  private:
    double q_ = 0, v_ = 0;
    double limit_ = 0;
    // v+ = av v + bv u,  q+ = q + aq v + bq u
    double av_ = 1, bv_ = 0, aq_ = 0, bq_ = 0;
};

} // namespace cutcell
