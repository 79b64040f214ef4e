#pragma once
// The quick-return mechanism driven by its crank motor: one degree of freedom q, Lagrange's
// equation with the configuration-dependent inertia
//   M(q) = J_crank + J_rocker rho_theta3^2 + m5 rho_y^2,
//   M(q) q'' + M'(q)/2 q'^2 = sat(tau) - b q' - tau_c tanh(q'/w_c) - m5 g rho_y + f_y rho_y + d,
// where f_y is the cutting force on the slider (Eq. 40: +contact_force, i.e. against the
// downward cut, while y' < 0 and the slider is over the workpiece), tau is the motor torque
// limited to +-torque_limit and d a disturbance torque. Slider dynamics of Eq. 34 follow from
// it with rho_y. RK4 with substeps; no allocation.
#include "core/machines/quick_return/whitworth.h"

namespace cutcell::quick_return {

struct CrankPlantParams {
    double slider_mass = 0.2;         // kg, m5 (slider + tool)
    double crank_inertia = 0.01;      // kg m^2, motor rotor through the gear + crank + pin block
    double rocker_inertia = 0.001;    // kg m^2, about O3
    double viscous = 0.01;            // N m s/rad
    double coulomb = 0.05;            // N m
    double torque_limit = 120;        // N m at the crank
    double gravity = 9.81;            // m/s^2, along -y
    double contact_force = 400;       // N, Eq. 40
    double cut_low = 0, cut_high = 0; // scale readings (m) between which the tool is in the work
    bool contact = false;             // Eq. 40 on (experiment 2) or off (experiment 1)
};

struct CrankState {
    double q = 0, dq = 0;
};

class CrankPlant {
  public:
    CrankPlant(const WhitworthDims& dims, const CrankPlantParams& params) : d_(dims), p_(params) {}
    void setState(double q, double dq) { s_ = {q, dq}; }
    const CrankState& state() const { return s_; }
    // One period of a held torque command; returns the torque applied (after the limit).
    double step(double torque, double disturbance, double dt, int substeps = 4);
    // Scale reading (m) and velocity of the slider now.
    double sliderPosition() const;
    double sliderVelocity() const;
    double contactForce() const { return lastContact_; } // N, of the last step
    double inertia(double q) const;                      // M(q)
    const WhitworthDims& dims() const { return d_; }
    const CrankPlantParams& params() const { return p_; }

  private:
    double accel(double q, double dq, double tau, double dist);
    WhitworthDims d_;
    CrankPlantParams p_;
    CrankState s_;
    double lastContact_ = 0;
};

} // namespace cutcell::quick_return
