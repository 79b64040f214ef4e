#include "core/machines/pipe_robot/plan_csv.h"
#include "core/common/c_format.h"

#include <cmath>
#include <cstdio>

namespace cutcell {

std::string pathCsv(const CutPlan& plan) {
    std::string out = "index,t_s,s_mm,phi_deg,x_mm,y_mm,z_mm,chuck_deg,tip_x_mm,tip_y_mm,tip_z_mm,"
                      "axis_x,axis_y,axis_z,direction_deviation_deg,ik_status\n";
    char buf[512];
    for (size_t i = 0; i < plan.knots.size(); ++i) {
        const PlannedPoint& p = plan.knots[i];
        snprintfC(buf, sizeof buf,
                  "%zu,%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.6f,%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.6f,%s\n",
                  i, p.t_s, p.cut.s_mm, rad2deg(p.cut.phi_rad), p.cut.p_main.x(), p.cut.p_main.y(),
                  p.cut.p_main.z(), rad2deg(p.chuck_rad), p.tip_base.x(), p.tip_base.y(),
                  p.tip_base.z(), p.approach_base.x(), p.approach_base.y(), p.approach_base.z(),
                  p.deviation_deg, toString(p.ik.status));
        out += buf;
    }
    return out;
}

std::string jointsCsv(const CutPlan& plan, double period_s) {
    std::string out = "t_s,q0_deg,q1_deg,q2_deg,q3_deg,q4_deg,q5_deg\n";
    const long steps = static_cast<long>(std::ceil(plan.cut_time_s / period_s - 1e-9));
    out.reserve(static_cast<size_t>(steps + 1) * 80);
    char buf[256];
    for (long k = 0; k <= steps; ++k) {
        const double t = static_cast<double>(k) * period_s;
        const JointVector q = plan.spline.evaluate(t).q;
        snprintfC(buf, sizeof buf, "%.6f,%.9f,%.9f,%.9f,%.9f,%.9f,%.9f\n", t, rad2deg(q[0]),
                  rad2deg(q[1]), rad2deg(q[2]), rad2deg(q[3]), rad2deg(q[4]), rad2deg(q[5]));
        out += buf;
    }
    return out;
}

} // namespace cutcell
