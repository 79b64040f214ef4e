#include "core/control/simc_tuning.h"

#include "core/common/bisect.h"
#include "core/common/types.h"
#include "core/control/joint_plant.h"
#include "core/control/pid_filter.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

// The rules (Skogestad 2003, Table 1, series/cascade PID form
// c(s) = Kc (1 + 1/(tau_I s)) (1 + tau_D s)):
//
//  - first-order with delay k e^(-theta s)/(tau1 s + 1), the root of the others:
//      Kc = (1/k) tau1/(tau_c + theta),  tau_I = min(tau1, 4 (tau_c + theta)),
//    with tau_c = theta for "tight" control, which Skogestad gives as a gain margin of about 3
//    (checked against the author's own summary, folk.ntnu.no/skoge/publications/2003/tuningPID/
//    smooth_tunings/README.txt: "Kc = (1/k) (tau1/(tauc+theta)), tauI = min[tau1, 4(tauc+theta)]",
//    "tauc = theta ... Gain Margin about 3").
//  - integrating process k' e^(-theta s)/s: the first-order rule for tau1 -> infinity with
//    k' = k/tau1, i.e. Kc = 1/(k' (tau_c + theta)), tau_I = 4 (tau_c + theta); a second lag tau2
//    (here tau1 = J/b of the joint) is cancelled by the series derivative time tau_D = tau2.
//  - double integrating k'' e^(-theta s)/s^2: Kc = 1/(4 k'' (tau_c + theta)^2),
//    tau_I = tau_D = 4 (tau_c + theta). This is the integrating-with-lag rule for a lag
//    tau2 = 4 (tau_c + theta) and k' = k'' tau2 (the two give the same parallel gains there).
// The paper's own text was not at hand here: the integrating rows are derived above from the
// first-order rule as the paper does, and the double-integrating row is the one of its Table 1.
//
// Effective delay theta = T/2 + tau_f: the zero-order hold of the sampled loop is a delay of
// half a period, and the PID's output filter 1/(tau_f s + 1) a lag that the half rule would
// count half as delay; it is counted whole (conservative: the filter is the drive's own, not a
// model error, and the loop keeps some margin for the lags nobody modelled).
//
// Conversion to the drives' parallel form Kp + Ki/s + Kd s:
//   Kp = Kc (1 + tau_D/tau_I), Ki = Kc/tau_I, Kd = Kc tau_D.

namespace cutcell {
namespace {

// Auto: a viscous friction so small that the lag tau1 = J/b is over this many times the
// loop's integral time 4 (tau_c + theta) is "b ~ 0": the joint is tuned as a double integrator.
// (With the lag rule, Ki = b/(4 (tau_c + theta)^2) would fade with b, and the loop would lose
// its integral action against constant loads such as gravity.)
constexpr double kDoubleIntegratorLagFactor = 100;

bool finitePositive(double v) {
    return std::isfinite(v) && v > 0;
}

using Complex = std::complex<double>;

// The sampled loop's pieces (the same discretisations as PidFilter and JointPlant).
struct SampledLoop {
    // PidFilter: x1+ = E x1 + g1 e, x2+ = x2 + g1 x1 + g2 e, u = c1 x1 + c2 x2 + d e.
    double E = 0, g1 = 0, g2 = 0, c1 = 0, c2 = 0, d = 0;
    // Plant: q+ = q + p v + gq u, v+ = Ev v + gv u.
    double p = 0, Ev = 0, gq = 0, gv = 0;

    SampledLoop(double J, double b, const PidGains& g, double T) {
        const PidFilter::Coefficients c = PidFilter(g, T).coefficients();
        E = c.E;
        g1 = c.g1;
        g2 = c.g2;
        c1 = c.c1;
        c2 = c.c2;
        d = c.d;
        const JointPlant::Coefficients j =
            JointPlant({J, b, std::numeric_limits<double>::max()}, T).coefficients();
        p = j.aq;
        Ev = j.av;
        gq = j.bq;
        gv = j.bv;
    }
    Complex controller(Complex z) const {
        const Complex x1 = g1 / (z - E);
        return d + c1 * x1 + c2 * (g1 * x1 + g2) / (z - 1.0);
    }
    Complex plant(Complex z) const { return ((z - Ev) * gq + p * gv) / ((z - 1.0) * (z - Ev)); }
    Complex loop(double w, double T) const {
        const Complex z = std::polar(1.0, w * T);
        return controller(z) * plant(z);
    }
    // Closed loop (r = 0) on the state (q, v, x1, x2), the controller's gains scaled by k.
    double spectralRadius(double k = 1) const {
        Eigen::Matrix4d A;
        // u = k (c1 x1 + c2 x2 - d q)
        const double uq = -k * d, u1 = k * c1, u2 = k * c2;
        A << 1 + gq * uq, p, gq * u1, gq * u2, //
            gv * uq, Ev, gv * u1, gv * u2,     //
            -g1, 0, E, 0,                      //
            -g2, 0, g1, 1;
        return Eigen::EigenSolver<Eigen::Matrix4d>(A, false).eigenvalues().cwiseAbs().maxCoeff();
    }
};

} // namespace

const char* toString(SimcRule r) {
    switch (r) {
    case SimcRule::Auto:
        return "auto";
    case SimcRule::IntegratingWithLag:
        return "integrating with lag";
    case SimcRule::DoubleIntegrating:
        return "double integrating";
    }
    return "auto";
}

SimcTuning simcTune(double J, double b, const SimcOptions& o) {
    if (!finitePositive(J)) throw std::invalid_argument("SIMC: the inertia must be > 0");
    if (!std::isfinite(b) || b < 0)
        throw std::invalid_argument("SIMC: the viscous friction must be >= 0");
    if (!finitePositive(o.period_s) || !finitePositive(o.tau_f_s))
        throw std::invalid_argument("SIMC: the control period and tau_f must be > 0");
    if (!std::isfinite(o.tau_c_s)) throw std::invalid_argument("SIMC: tau_c must be finite");

    SimcTuning t;
    t.inertia_kg_m2 = J;
    t.viscous_nm_s_per_rad = b;
    t.theta_s = o.period_s / 2 + o.tau_f_s;
    t.tau_c_s = o.tau_c_s > 0 ? o.tau_c_s : t.theta_s;
    const double closed = t.tau_c_s + t.theta_s; // tau_c + theta
    t.rule = o.rule;
    if (t.rule == SimcRule::Auto)
        t.rule = b > 0 && J / b <= kDoubleIntegratorLagFactor * 4 * closed
                     ? SimcRule::IntegratingWithLag
                     : SimcRule::DoubleIntegrating;
    if (t.rule == SimcRule::IntegratingWithLag) {
        if (b <= 0) throw std::invalid_argument("SIMC: the integrating-with-lag rule needs b > 0");
        const double kPrime = 1 / b;
        t.kc = 1 / (kPrime * closed);
        t.tau_i_s = 4 * closed;
        t.tau_d_s = J / b;
    } else {
        const double kDoublePrime = 1 / J;
        t.kc = 1 / (4 * kDoublePrime * closed * closed);
        t.tau_i_s = 4 * closed;
        t.tau_d_s = 4 * closed;
    }
    t.gains.kp = t.kc * (1 + t.tau_d_s / t.tau_i_s);
    t.gains.ki = t.kc / t.tau_i_s;
    t.gains.kd = t.kc * t.tau_d_s;
    t.gains.tau_f = o.tau_f_s;
    return t;
}

LoopMargins sampledLoopMargins(double J, double b, const PidGains& gains, double T) {
    if (!finitePositive(J) || !std::isfinite(b) || b < 0 || !finitePositive(T) ||
        !finitePositive(gains.tau_f))
        throw std::invalid_argument("loop margins: J, T and tau_f must be > 0, b >= 0");
    const SampledLoop loop(J, b, gains, T);
    LoopMargins m;
    m.spectral_radius = loop.spectralRadius();
    m.stable = m.spectral_radius < 1;

    // The frequency response from far below the loop's corners up to the Nyquist frequency.
    const double nyquist = kPi / T;
    const double lo = nyquist * 1e-7;
    constexpr int kPoints = 7000;
    std::vector<double> w(kPoints);
    std::vector<Complex> L(kPoints);
    for (int i = 0; i < kPoints; ++i) {
        // The last point just below Nyquist (z = -1 is evaluated on its own).
        w[i] = lo * std::pow(nyquist * (1 - 1e-9) / lo, static_cast<double>(i) / (kPoints - 1));
        L[i] = loop.loop(w[i], T);
    }
    m.gain_margin = std::numeric_limits<double>::infinity();
    const auto phaseCrossing = [&](double wc) {
        const Complex l = loop.loop(wc, T);
        if (l.real() < 0 && std::abs(l) < 1 && 1 / std::abs(l) < m.gain_margin) {
            m.gain_margin = 1 / std::abs(l);
            m.phase_crossover_rad_s = wc;
        }
    };
    m.phase_margin_deg = std::numeric_limits<double>::infinity();
    for (int i = 1; i < kPoints; ++i) {
        // Crossing the negative real axis: the gain that takes the curve through -1.
        if ((L[i - 1].imag() < 0) != (L[i].imag() < 0) && (L[i - 1].real() < 0 || L[i].real() < 0))
            phaseCrossing(
                bisect([&](double x) { return loop.loop(x, T).imag(); }, w[i - 1], w[i], 80));
        // |L| = 1: the phase margin.
        if ((std::abs(L[i - 1]) < 1) != (std::abs(L[i]) < 1)) {
            const double wc =
                bisect([&](double x) { return std::abs(loop.loop(x, T)) - 1; }, w[i - 1], w[i], 80);
            double phase = std::arg(loop.loop(wc, T)) * 180 / kPi;
            if (phase > 0) phase -= 360;
            if (180 + phase < m.phase_margin_deg) {
                m.phase_margin_deg = 180 + phase;
                m.gain_crossover_rad_s = wc;
            }
        }
    }
    // At the Nyquist frequency the loop is real.
    const Complex atNyquist = loop.controller(-1.0) * loop.plant(-1.0);
    if (atNyquist.real() < 0 && std::abs(atNyquist) < 1 &&
        1 / std::abs(atNyquist) < m.gain_margin) {
        m.gain_margin = 1 / std::abs(atNyquist);
        m.phase_crossover_rad_s = nyquist;
    }
    return m;
}

} // namespace cutcell
