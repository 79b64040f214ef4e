#include "core/machines/profile_cutter/profile_csv.h"
#include "core/common/c_format.h"

#include <cinttypes>
#include <cstdio>

namespace cutcell {

std::string profilePathCsv(const ProfileCut& cut, const PulseSchedule& sch) {
    std::string out =
        "index,t_s,s_mm,beta_deg,x_mm,y_mm,z_mm,X_mm,A_deg,pipe,x_pulse_pos,a_pulse_pos,"
        "step_x_pulses,step_a_pulses,step_dt_s,x_rate_hz,a_rate_hz\n";
    char buf[512];
    double t = 0, s = 0;
    std::int64_t px = sch.x_start_pulses, pa = sch.a_start_pulses;
    for (size_t i = 0; i <= cut.points.size(); ++i) {
        const ProfilePoint p = cut.closedAt(i);
        const bool closing = i == cut.points.size();
        const PulseStep step = closing || i >= sch.steps.size() ? PulseStep{} : sch.steps[i];
        snprintfC(buf, sizeof buf,
                  "%zu,%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.6f,%.6f,%d,%" PRId64 ",%" PRId64 ",%" PRId64
                  ",%" PRId64 ",%.9f,%.3f,%.3f\n",
                  i, t, s, closing ? 360.0 : p.beta_deg, p.p_main.x(), p.p_main.y(), p.p_main.z(),
                  p.x_mm, p.a_deg, p.pipe, px, pa, step.x_pulses, step.a_pulses, step.dt_s,
                  step.x_rate_hz, step.a_rate_hz);
        out += buf;
        t += step.dt_s;
        s += step.ds_mm;
        px += step.x_pulses;
        pa += step.a_pulses;
    }
    return out;
}

} // namespace cutcell
