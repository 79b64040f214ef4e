#include "core/control/joint_plant.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

void JointPlant::configure(const JointPlantParams& p, double T) {
    const double J = p.inertia_kg_m2, b = p.viscous_nm_s_per_rad;
    limit_ = p.torque_limit_nm;
    if (b > 1e-12) {
        const double a = b / J;
        const double oneMinusE = -std::expm1(-a * T);
        av_ = 1 - oneMinusE;
        bv_ = oneMinusE / b;
        aq_ = oneMinusE / a;
        bq_ = (T - oneMinusE / a) / b;
    } else {
        av_ = 1;
        bv_ = T / J;
        aq_ = T;
        bq_ = T * T / (2 * J);
    }
    q_ = v_ = 0;
}

double JointPlant::step(double torqueCommand) {
    const double u = std::clamp(torqueCommand, -limit_, limit_);
    q_ += aq_ * v_ + bq_ * u;
    v_ = av_ * v_ + bv_ * u;
    return u;
}

} // namespace cutcell
