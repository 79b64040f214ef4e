#include "core/control/pid_filter.h"

#include <cmath>

namespace cutcell {

void PidFilter::configure(const PidGains& g, double T) {
    const double tau = g.tau_f;
    e_ = std::exp(-T / tau);
    // -expm1 keeps 1 - E accurate when T << tau.
    const double oneMinusE = -std::expm1(-T / tau);
    g1_ = tau * oneMinusE;
    g2_ = tau * (T - tau * oneMinusE);
    c1_ = g.kp / tau - g.kd / (tau * tau);
    c2_ = g.ki / tau;
    d_ = g.kd / tau;
    reset();
}

double PidFilter::step(double e) {
    const double v = output(e);
    const double x1 = x1_;
    x1_ = e_ * x1 + g1_ * e;
    x2_ = x2_ + g1_ * x1 + g2_ * e;
    return v;
}

} // namespace cutcell
