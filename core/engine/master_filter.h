#pragma once
// The master position filter of a master-axis coupling: an alpha-beta tracker on the
// encoder's position. It follows a master at constant speed with no lag, and its error on a
// master whose speed changes or whose reading is quantised / noisy is bounded by two figures
// of the filter itself (l1 norms of its impulse responses):
//   |x_true - x_filtered| <= accelGain() * a_max * T^2 + noiseGain() * d_max
// where a_max bounds the master's acceleration and d_max the measurement error (half a count
// of quantisation plus the noise amplitude). Tests check the coupling against this bound.
//
// update() is allocation-free (engine cycle); the gains are computed outside the cycle.
#include <cmath>

namespace cutcell {

class MasterFilter {
  public:
    // alpha in (0, 1]; beta = alpha^2 / (2 - alpha) (Benedict-Bordner) when beta <= 0.
    explicit MasterFilter(double alpha = 0.2, double beta = 0) { setGains(alpha, beta); }
    void setGains(double alpha, double beta = 0) {
        alpha_ = alpha;
        beta_ = beta > 0 ? beta : alpha * alpha / (2 - alpha);
    }
    double alpha() const { return alpha_; }
    double beta() const { return beta_; }

    void reset(double position, double velocity) {
        x_ = position;
        v_ = velocity;
        lastAge_ = 0;
    }
    // One measurement per period T; returns the filtered position. A measurement `age` periods
    // old (late over a bus) is compared with the estimate of its own time, once: the same
    // reading again (its age one more than last time: no new TPDO) only predicts - fed again
    // and again its residual would close a loop through v with gain beta (age - 1), unstable.
    double update(double z, double T, int age = 0) {
        const double predicted = x_ + v_ * T;
        const bool sameReading = age > 0 && age == lastAge_ + 1;
        lastAge_ = age;
        if (sameReading) return x_ = predicted;
        const double r = z - (predicted - age * v_ * T);
        x_ = predicted + alpha_ * r;
        v_ += beta_ / T * r;
        return x_;
    }
    double position() const { return x_; }
    double velocity() const { return v_; }

    // Sum of |impulse response| from a measurement error to the estimate.
    double noiseGain() const {
        MasterFilter f(alpha_, beta_);
        f.reset(0, 0);
        double sum = 0;
        for (int k = 0; k < 200000; ++k) {
            const double x = f.update(k == 0 ? 1.0 : 0.0, 1.0);
            sum += std::fabs(x);
            if (k > 100 && std::fabs(x) < 1e-18) break;
        }
        return sum;
    }
    // Sum of |response| of the error (true - estimate) to a unit second difference of the
    // true position (T = 1): the master's z_k = k + 1 from rest at 0.
    double accelGain() const {
        MasterFilter f(alpha_, beta_);
        f.reset(0, 0);
        double sum = 0;
        for (int k = 0; k < 200000; ++k) {
            const double z = static_cast<double>(k + 1);
            const double e = z - f.update(z, 1.0);
            sum += std::fabs(e);
            if (k > 100 && std::fabs(e) < 1e-18) break;
        }
        return sum;
    }

  private:
    double alpha_ = 0.2, beta_ = 0.02;
    double x_ = 0, v_ = 0;
    int lastAge_ = 0;
};

} // namespace cutcell
