#include "core/machines/quick_return/crank_plant.h"

#include <algorithm>
#include <cmath>

namespace cutcell::quick_return {

double CrankPlant::inertia(double q) const {
    const WhitworthPose p = forwardKinematics(d_, q);
    if (!p.closes) return p_.crank_inertia;
    const auto rho = extendedJacobian(d_, q, p);
    return p_.crank_inertia + p_.rocker_inertia * rho[2] * rho[2] +
           p_.slider_mass * rho[4] * rho[4];
}

double CrankPlant::accel(double q, double dq, double tau, double dist) {
    const WhitworthPose p = forwardKinematics(d_, q);
    if (!p.closes) return 0;
    const auto rho = extendedJacobian(d_, q, p);
    const double M =
        p_.crank_inertia + p_.rocker_inertia * rho[2] * rho[2] + p_.slider_mass * rho[4] * rho[4];
    constexpr double h = 1e-6;
    const double dM = (inertia(q + h) - inertia(q - h)) / (2 * h);
    const double y = p.y + d_.scale_offset, dy = rho[4] * dq;
    const double lo = std::min(p_.cut_low, p_.cut_high), hi = std::max(p_.cut_low, p_.cut_high);
    const double fy = p_.contact && dy < 0 && y >= lo && y <= hi ? p_.contact_force : 0;
    lastContact_ = fy;
    const double friction = p_.viscous * dq + p_.coulomb * std::tanh(dq / 0.01);
    return (tau - friction - 0.5 * dM * dq * dq - p_.slider_mass * p_.gravity * rho[4] +
            fy * rho[4] + dist) /
           M;
}

double CrankPlant::step(double torque, double disturbance, double dt, int substeps) {
    const double tau = std::clamp(torque, -p_.torque_limit, p_.torque_limit);
    const double h = dt / substeps;
    double contact = 0;
    for (int i = 0; i < substeps; ++i) {
        const double q = s_.q, v = s_.dq;
        const double a1 = accel(q, v, tau, disturbance);
        contact = std::max(contact, lastContact_);
        const double a2 = accel(q + 0.5 * h * v, v + 0.5 * h * a1, tau, disturbance);
        const double a3 =
            accel(q + 0.5 * h * (v + 0.5 * h * a1), v + 0.5 * h * a2, tau, disturbance);
        const double a4 = accel(q + h * (v + 0.5 * h * a2), v + h * a3, tau, disturbance);
        s_.q = q + h * v + h * h / 6 * (a1 + a2 + a3);
        s_.dq = v + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    }
    lastContact_ = contact;
    return tau;
}

double CrankPlant::sliderPosition() const {
    return forwardKinematics(d_, s_.q).y + d_.scale_offset;
}

double CrankPlant::sliderVelocity() const {
    const WhitworthPose p = forwardKinematics(d_, s_.q);
    return p.closes ? extendedJacobian(d_, s_.q, p)[4] * s_.dq : 0;
}

} // namespace cutcell::quick_return
