#pragma once
// A point-to-point joint move (homing, jog, approach to the cut): a quintic blend from rest to
// rest, zero velocity and acceleration at both ends, no axis faster than its speed limit.
// Evaluated by path time like the cut's spline, so feed hold and abort time-scale it too.
#include "core/common/types.h"
#include "core/trajectory/joint_spline.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

struct JointMove {
    JointVector from = JointVector::Zero();
    JointVector to = JointVector::Zero();
    double duration = 0;

    // The quintic's peak speed is 15/8 of the mean: the slowest axis sets the duration.
    static JointMove make(const JointVector& from, const JointVector& to,
                          const JointVector& speedLimit) {
        JointMove m;
        m.from = from;
        m.to = to;
        for (int i = 0; i < kMaxAxes; ++i)
            if (speedLimit[i] > 0)
                m.duration =
                    std::max(m.duration, 15.0 / 8.0 * std::fabs(to[i] - from[i]) / speedLimit[i]);
        return m;
    }

    JointSample at(double t) const {
        JointSample s;
        if (!(duration > 0) || t >= duration) {
            s.q = to;
            return s;
        }
        if (!(t > 0)) {
            s.q = from;
            return s;
        }
        const double u = t / duration;
        const double u2 = u * u, u3 = u2 * u;
        const double p = u3 * (10 - 15 * u + 6 * u2);
        const double dp = 30 * u2 * (1 - 2 * u + u2) / duration;
        const double ddp = 60 * u * (1 - 3 * u + 2 * u2) / (duration * duration);
        const JointVector d = to - from;
        s.q = from + d * p;
        s.qd = d * dp;
        s.qdd = d * ddp;
        return s;
    }
};

} // namespace cutcell
