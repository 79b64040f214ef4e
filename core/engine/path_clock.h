#pragma once
// A time that runs at a rate ramped linearly toward a target (feed hold, abort, override and a
// category-1 stop act on the rate): the engine's set-point moves (home, jog, approach) and the
// joint spline's path time. Allocation-free; advanced once per engine cycle.
#include <algorithm>
#include <cstdint>

namespace cutcell {

class PathClock {
  public:
    double time() const { return tau_; }
    double rate() const { return rate_; }

    void restart(double time, double rate) {
        tau_ = anchorTau_ = time;
        rate_ = rate;
        anchorCycles_ = 0;
    }

    // One cycle of period T: the rate moves toward `target` by at most `rateStep`, the time by
    // the mean rate; capped at `end`. While the rate is steady the time is computed from an
    // anchor (tau0 + rate * n * T) so no rounding accumulates: at rate 1 from 0 it is n * T,
    // exactly the offline simulation's sample times.
    void step(double target, double T, double rateStep, double end) {
        const double old = rate_;
        rate_ = rate_ < target ? std::min(target, rate_ + rateStep)
                               : std::max(target, rate_ - rateStep);
        if (rate_ != old) {
            tau_ += 0.5 * (old + rate_) * T;
            anchorTau_ = tau_;
            anchorCycles_ = 0;
        } else {
            ++anchorCycles_;
            tau_ = anchorTau_ + rate_ * (static_cast<double>(anchorCycles_) * T);
        }
        if (tau_ > end) tau_ = end;
    }

  private:
    double tau_ = 0, rate_ = 0, anchorTau_ = 0;
    std::uint64_t anchorCycles_ = 0;
};

} // namespace cutcell
