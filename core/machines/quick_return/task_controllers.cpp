#include "core/machines/quick_return/task_controllers.h"

#include <algorithm>
#include <cmath>

namespace cutcell::quick_return {

const char* toString(ControllerKind k) {
    switch (k) {
    case ControllerKind::Ffc:
        return "ffc";
    case ControllerKind::Lqt:
        return "lqt";
    case ControllerKind::Smc:
        return "smc";
    case ControllerKind::Osmc:
        return "osmc";
    }
    return "?";
}

Gain2 ffcGain(const ControllerParams& p) {
    // det(sI - A + B K) = s^2 + b k2 s + b k1 = s^2 + 2 xi wn s + wn^2.
    const double m = p.model_mass;
    return {m * p.ffc_wn2, m * 2 * p.ffc_xi * std::sqrt(p.ffc_wn2)};
}

Riccati2 lqtRiccati(const ControllerParams& p) {
    // Double integrator, B = [0; b]: closed form of the ARE (P positive definite).
    const double b = 1 / p.model_mass, R = p.lqt_r;
    Riccati2 r;
    r.p12 = std::sqrt(p.lqt_q1 * R) / b;
    r.p22 = std::sqrt(R * (2 * r.p12 + p.lqt_q2)) / b;
    r.p11 = b * b * r.p12 * r.p22 / R;
    r.k = {b * r.p12 / R, b * r.p22 / R};
    return r;
}

double lqtResidual(const ControllerParams& p, const Riccati2& r) {
    const double b = 1 / p.model_mass, R = p.lqt_r;
    // A^T P + P A = [0 p11; p11 2 p12]; P B R^-1 B^T P = b^2/R [p12; p22][p12 p22].
    const double e11 = -b * b / R * r.p12 * r.p12 + p.lqt_q1;
    const double e12 = r.p11 - b * b / R * r.p12 * r.p22;
    const double e22 = 2 * r.p12 - b * b / R * r.p22 * r.p22 + p.lqt_q2;
    return std::max({std::fabs(e11), std::fabs(e12), std::fabs(e22)});
}

namespace {
// Reduced problem in Psi = T e, T = [1 0; 0 1/b]: A_bar = [0 b; 0 0], B_bar = [0; 1].
OsmcSurface solveSurface(double b, double q11, double q12, double q22) {
    OsmcSurface s;
    s.a12 = b;
    s.q22 = q22;
    s.a_hat = 0 - s.a12 * q12 / q22; // A11 - A12 Q22^-1 Q12^T (the seed prints A22: Eq. 23)
    s.q_bar = q11 - q12 * q12 / q22;
    // 2 a_hat P - (a12^2 / q22) P^2 + q_bar = 0, positive root.
    const double g = s.a12 * s.a12 / q22;
    s.p = (s.a_hat + std::sqrt(s.a_hat * s.a_hat + g * s.q_bar)) / g;
    s.residual = 2 * s.a_hat * s.p - g * s.p * s.p + s.q_bar;
    const double c1bar = (s.a12 * s.p + q12) / q22; // Eq. 26
    // s = C_bar Psi = c1bar e1 + e2 / b.
    s.c1 = c1bar;
    s.c2 = 1 / b;
    return s;
}
} // namespace

OsmcSurface osmcSurface(const ControllerParams& p) {
    const double b = 1 / p.model_mass;
    // T^-T Q T^-1 with T^-1 = diag(1, b): [q11, b q12; b q12, b^2 q22].
    return solveSurface(b, p.osmc_q11, b * p.osmc_q12, b * b * p.osmc_q22);
}

OsmcSurface osmcSurfacePrinted(const ControllerParams& p) {
    const double b = 1 / p.model_mass;
    // T Q T^-1 = [q11, b q12; q12 / b, q22] (not symmetric); its Q12, Q22 as the seed reads them.
    return solveSurface(b, p.osmc_q11, b * p.osmc_q12, p.osmc_q22);
}

void TaskController::configure(ControllerKind kind, const ControllerParams& p) {
    kind_ = kind;
    p_ = p;
    if (kind == ControllerKind::Ffc) k_ = ffcGain(p);
    if (kind == ControllerKind::Lqt) k_ = lqtRiccati(p).k;
    surf_ = osmcSurface(p);
    s0_ = kx_ = s_ = 0;
}

void TaskController::restart(double e1, double e2) {
    s0_ = surf_.c1 * e1 + surf_.c2 * e2;
    kx_ = 0;
}

double TaskController::update(double e1, double e2, double ddy_d, double dt, double t_since_start) {
    const double m = p_.model_mass, ff = m * (ddy_d + p_.gravity);
    switch (kind_) {
    case ControllerKind::Ffc:
    case ControllerKind::Lqt:
        s_ = 0;
        return ff + k_.k1 * e1 + k_.k2 * e2;
    case ControllerKind::Smc: {
        s_ = p_.smc_c * e1 + e2;
        const double sat = std::clamp(s_ / p_.smc_phi, -1.0, 1.0);
        return ff + m * p_.smc_c * e2 + p_.smc_eta * sat;
    }
    case ControllerKind::Osmc: {
        s_ = surf_.c1 * e1 + surf_.c2 * e2;
        const double sigma = s_ - s0_ * std::exp(-p_.osmc_lambda * t_since_start);
        kx_ += (sigma > 0 ? 1.0 : sigma < 0 ? -1.0 : 0.0) * dt;
        const double sx = sigma + p_.osmc_k2 * kx_;
        return p_.osmc_k1 * sx;
    }
    }
    return 0;
}

} // namespace cutcell::quick_return
