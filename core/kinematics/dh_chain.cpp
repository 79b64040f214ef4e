#include "core/kinematics/dh_chain.h"
#include "core/common/sin_cos.h"

#include <cmath>

namespace cutcell {

Pose dhTransform(const DhLink& l, double theta) {
    const double th = theta + l.theta_offset_rad;
    double ct, st;
    sinCos(th, st, ct);
    const double ca = std::cos(l.alpha_rad), sa = std::sin(l.alpha_rad);
    Pose T = Pose::Identity();
    T.linear() << ct, -st * ca, st * sa, st, ct * ca, -ct * sa, 0, sa, ca;
    T.translation() << l.a_mm * ct, l.a_mm * st, l.d_mm;
    return T;
}

Pose DhChain::forward(const double* q) const {
    Pose T = Pose::Identity();
    for (size_t i = 0; i < links_.size(); ++i)
        T = T * dhTransform(links_[i], q[i]);
    return T;
}

void DhChain::frames(const double* q, Pose* out) const {
    out[0] = Pose::Identity();
    for (size_t i = 0; i < links_.size(); ++i)
        out[i + 1] = out[i] * dhTransform(links_[i], q[i]);
}

} // namespace cutcell
