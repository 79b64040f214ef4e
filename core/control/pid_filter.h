#pragma once
// PID with a first-order filter (seed Eq. 69-79):
//   C(s) = (Kd s + Kp + Ki / s) / (tau_f s + 1)
//   x1' = -x1 / tau_f + e,  x2' = x1,  V = (Kp/tau_f - Kd/tau_f^2) x1 + (Ki/tau_f) x2 + (Kd/tau_f)
//   e
// discretised exactly for an error held constant over each period (zero-order hold): the
// discrete output equals the continuous one at every sample for piecewise-constant errors.
// Real-time safe: step() neither allocates nor locks.
#include "core/job/job.h"

namespace cutcell {

class PidFilter {
  public:
    PidFilter() = default;
    PidFilter(const PidGains& gains, double period_s) { configure(gains, period_s); }

    void configure(const PidGains& gains, double period_s);
    void reset() { x1_ = x2_ = 0; }
    // The state of a loop that has been holding still (zero error) with this output: the
    // integral carries it, e.g. the torque that holds an arm against gravity (no bump when a
    // drive takes over from its brake). Needs Ki > 0; otherwise like reset().
    void preload(double output) {
        x1_ = 0;
        x2_ = c2_ != 0 ? output / c2_ : 0;
    }
    // Output for the error e at this sample; the state then advances one period.
    double step(double e);
    // Output without advancing (what step() would return).
    double output(double e) const { return c1_ * x1_ + c2_ * x2_ + d_ * e; }

    // The discrete coefficients: x1+ = E x1 + g1 e, x2+ = x2 + g1 x1 + g2 e,
    // V = c1 x1 + c2 x2 + d e (for analyses of the sampled loop, e.g. its margins).
    struct Coefficients {
        double E, g1, g2, c1, c2, d;
    };
    Coefficients coefficients() const { return {e_, g1_, g2_, c1_, c2_, d_}; }

    double x1() const { return x1_; }
    double x2() const { return x2_; }

  private:
    double x1_ = 0, x2_ = 0;
    double e_ = 0;  // exp(-T / tau)
    double g1_ = 0; // tau (1 - E): x1 gain from e, x2 gain from x1
    double g2_ = 0; // tau (T - tau (1 - E)): x2 gain from e
    double c1_ = 0, c2_ = 0, d_ = 0;
};

} // namespace cutcell
