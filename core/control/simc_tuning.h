#pragma once
// Skogestad's SIMC tuning rules (S. Skogestad, "Simple analytic rules for model reduction and PID
// controller tuning", J. Process Control 13 (2003) 291-309; the seed's ref. [11]) for a joint
// seen from its drive as
//
//   G(s) = e^(-theta s) / (s (J s + b))  =  k' e^(-theta s) / (s (tau1 s + 1)),
//   k' = 1/b, tau1 = J/b                         (integrating process with lag), or
//   G(s) = k'' e^(-theta s) / s^2, k'' = 1/J     (double integrating process, b ~ 0),
//
// and the check of a tuning on the sampled loop it runs in (the PidFilter of pid_filter.h at the
// control period T on that plant behind a zero-order hold): closed-loop stability and the gain
// and phase margins from the loop's frequency response. simc_tuning.cpp has the rules, their
// source and the conversion to the parallel gains the drives use.
#include "core/job/job.h"

namespace cutcell {

enum class SimcRule {
    Auto,               // integrating with lag; double integrating when b is ~0 (see .cpp)
    IntegratingWithLag, // Kc = 1/(k' (tau_c + theta)), tau_I = 4 (tau_c + theta), tau_D = tau1
    DoubleIntegrating,  // Kc = 1/(4 k'' (tau_c + theta)^2), tau_I = tau_D = 4 (tau_c + theta)
};
const char* toString(SimcRule r); // "integrating with lag", "double integrating"

struct SimcOptions {
    double period_s = 0.001; // control period T (the loop's zero-order hold)
    double tau_f_s = 0.002;  // the PID's output filter (kept; counted as delay)
    double tau_c_s = 0;      // desired closed-loop time constant; <= 0: tau_c = theta (tight)
    SimcRule rule = SimcRule::Auto;
};

// One joint's tuning with every intermediate figure, for an explanation.
struct SimcTuning {
    SimcRule rule = SimcRule::IntegratingWithLag; // the rule used (never Auto)
    double inertia_kg_m2 = 0;                     // J
    double viscous_nm_s_per_rad = 0;              // b
    double theta_s = 0;                           // effective delay: T/2 + tau_f
    double tau_c_s = 0;
    double kc = 0;      // series PID: Kc (1 + 1/(tau_I s)) (1 + tau_D s), N m/rad
    double tau_i_s = 0; // series integral time
    double tau_d_s = 0; // series derivative time
    PidGains gains;     // parallel: Kp + Ki/s + Kd s, with the options' tau_f
};

// Throws std::invalid_argument for J <= 0, b < 0, T <= 0 or tau_f <= 0 (or not finite).
SimcTuning simcTune(double inertia_kg_m2, double viscous_nm_s_per_rad, const SimcOptions& options);

// The sampled loop L(z) = C(z) G(z): the PidFilter's exact discretisation (pid_filter.h) times
// the plant 1/(s (J s + b)) behind a zero-order hold, the torque of sample k held over
// [kT, (k+1) T] (as the offline simulation and the engine apply it).
struct LoopMargins {
    bool stable = false;        // every closed-loop pole inside the unit circle
    double spectral_radius = 0; // largest closed-loop pole magnitude
    double gain_margin = 0;     // factor on the loop gain to the -180 deg crossing (inf: none)
    double phase_crossover_rad_s = 0;
    double phase_margin_deg = 0; // at the gain crossover |L| = 1 (the lowest, if several)
    double gain_crossover_rad_s = 0;
};
LoopMargins sampledLoopMargins(double inertia_kg_m2, double viscous_nm_s_per_rad,
                               const PidGains& gains, double period_s);

} // namespace cutcell
