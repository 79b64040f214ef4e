#pragma once
// The task-space controllers of seed 004 on the slider model (Eq. 8/10/36):
//   z = [y, y'],  z' = A z + B (u + d),  A = [0 1; 0 0],  B = [0; b],  b = 1/m,
// with the error e = z_d - z (Eq. 12). u is the force on the slider (N); the Jacobian
// compensator (Eq. 33) maps it to crank torque. Feedback signs are those that stabilise with
// e = z_d - z: u_f = +K e (the seed prints u_f = -K e, which is positive feedback).
//   FFC  (Eq. 37-38): u = m (y_d'' + g) + K e, K = m [wn^2, 2 xi wn].
//   LQT  (Eq. 39):    u = m (y_d'' + g) + K e, K = R^-1 B^T P, P of the ARE with Q, R.
//   SMC  (plain):     s = c e1 + e2, u = m (y_d'' + g + c e2) + eta sat(s / phi).
//   OSMC (Sec. 5):    s = C e with C from the Riccati equation of the reduced problem
//                     (Eq. 20-26, Q transformed as T^-T Q T^-1), then the second-order SMC
//                     (Eq. 27-30): sigma = s - s0 exp(-lambda (t - t0)), k_x' = sign(sigma),
//                     s_x = sigma + k2 k_x, u = k1 s_x. No model feed-forward.
// The feed-forward of FFC/LQT/SMC includes the slider's known weight m g (Eq. 36).
#include <array>

namespace cutcell::quick_return {

enum class ControllerKind { Ffc, Lqt, Smc, Osmc };
const char* toString(ControllerKind k);
inline constexpr std::array<ControllerKind, 4> kAllControllers{
    ControllerKind::Ffc, ControllerKind::Lqt, ControllerKind::Smc, ControllerKind::Osmc};

struct ControllerParams {
    double model_mass = 0.2; // kg: the slider mass the controllers are designed with (b = 1/m)
    double gravity = 9.81;
    // FFC
    double ffc_wn2 = 1000, ffc_xi = 1;
    // LQT: Q = diag(q1, q2), R
    double lqt_q1 = 1e6, lqt_q2 = 1e3, lqt_r = 1;
    // plain SMC
    double smc_c = 30, smc_eta = 200, smc_phi = 0.05;
    // OSMC: Q = [q11 q12; q12 q22] on e, lambda, k1, k2
    double osmc_q11 = 900, osmc_q12 = 0, osmc_q22 = 1;
    double osmc_lambda = 20, osmc_k1 = 2000, osmc_k2 = 1;
};

// Gains of a 2-state feedback u_f = K e.
struct Gain2 {
    double k1 = 0, k2 = 0;
};
Gain2 ffcGain(const ControllerParams& p);
// LQR of the double integrator with input gain b: the ARE's P (symmetric) and K = R^-1 B^T P.
struct Riccati2 {
    double p11 = 0, p12 = 0, p22 = 0;
    Gain2 k;
};
Riccati2 lqtRiccati(const ControllerParams& p);
// Residual of A^T P + P A - P B R^-1 B^T P + Q (max abs entry) for a check.
double lqtResidual(const ControllerParams& p, const Riccati2& r);

// The OSMC surface s = C e = c1 e1 + c2 e2 (c2 = 1/b: C B = 1) and the scalar ARE of the
// reduced problem: A_hat P + P A_hat - P A12 Q22^-1 A12 P + Q_bar = 0.
struct OsmcSurface {
    double c1 = 0, c2 = 0;
    double p = 0;                            // the ARE's solution
    double a_hat = 0, a12 = 0;               // A11 - A12 Q22^-1 Q12^T, A12
    double q_bar = 0, q22 = 0;               // of T^-T Q T^-1
    double residual = 0;                     // of the ARE at p
    double slope() const { return c1 / c2; } // e2 = -slope e1 on the surface
};
OsmcSurface osmcSurface(const ControllerParams& p);
// The same with the seed's Eq. 21 as printed (T Q T^-1): the erratum's surface.
OsmcSurface osmcSurfacePrinted(const ControllerParams& p);

// One controller with its state (the OSMC's k_x, s0). No allocation.
class TaskController {
  public:
    void configure(ControllerKind kind, const ControllerParams& p);
    // Restarts the sliding-mode state (the seed's t0) with the error now.
    void restart(double e1, double e2);
    // u (N) for the error e = z_d - z, the reference acceleration, dt since the last call and
    // the time since restart.
    double update(double e1, double e2, double ddy_d, double dt, double t_since_start);
    ControllerKind kind() const { return kind_; }
    double surface() const { return s_; }

  private:
    ControllerKind kind_ = ControllerKind::Osmc;
    ControllerParams p_;
    Gain2 k_;
    OsmcSurface surf_;
    double s0_ = 0, kx_ = 0, s_ = 0;
};

} // namespace cutcell::quick_return
