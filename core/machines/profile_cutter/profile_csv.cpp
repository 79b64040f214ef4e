#include "core/machines/profile_cutter/profile_csv.h"
#include "core/common/c_format.h"

#include <cinttypes>
#include <cmath>
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

std::string profilePathCsv(const ProfileCut& cut, const PulseSchedule& sch,
                           const ProfileLeads& leads, double speed_mm_s) {
    if (!leads.used) return profilePathCsv(cut, sch);
    std::string out =
        "index,t_s,s_mm,beta_deg,x_mm,y_mm,z_mm,X_mm,A_deg,pipe,x_pulse_pos,a_pulse_pos,"
        "step_x_pulses,step_a_pulses,step_dt_s,x_rate_hz,a_rate_hz,part\n";
    char buf[512];
    const double radPerPulse = deg2rad(sch.deg_per_pulse_a);
    auto xPulses = [&](double x) {
        return static_cast<std::int64_t>(std::llround(x / sch.mm_per_pulse_x));
    };
    auto aPulses = [&](double a) {
        return static_cast<std::int64_t>(std::llround(a / sch.deg_per_pulse_a));
    };
    // The step from the pulse position (px, pa) to `next`, at the cutting speed.
    auto stepTo = [&](std::int64_t px, std::int64_t pa, const ProfilePoint& next) {
        PulseStep st;
        st.x_pulses = xPulses(next.x_mm) - px;
        st.a_pulses = aPulses(next.a_deg) - pa;
        st.ds_mm = std::hypot(static_cast<double>(st.x_pulses) * sch.mm_per_pulse_x,
                              cut.work_radius_mm * static_cast<double>(st.a_pulses) * radPerPulse);
        st.dt_s = speed_mm_s > 0 ? st.ds_mm / speed_mm_s : 0;
        if (st.dt_s > 0) {
            st.x_rate_hz = static_cast<double>(std::llabs(st.x_pulses)) / st.dt_s;
            st.a_rate_hz = static_cast<double>(std::llabs(st.a_pulses)) / st.dt_s;
        }
        return st;
    };
    size_t index = 0;
    double t = 0, s = 0;
    auto row = [&](const ProfilePoint& p, const ProfilePoint* onEdge, double beta, std::int64_t px,
                   std::int64_t pa, const PulseStep& step, const char* part) {
        if (onEdge)
            snprintfC(buf, sizeof buf,
                      "%zu,%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.6f,%.6f,%d,%" PRId64 ",%" PRId64
                      ",%" PRId64 ",%" PRId64 ",%.9f,%.3f,%.3f,%s\n",
                      index, t, s, beta, p.p_main.x(), p.p_main.y(), p.p_main.z(), p.x_mm, p.a_deg,
                      p.pipe, px, pa, step.x_pulses, step.a_pulses, step.dt_s, step.x_rate_hz,
                      step.a_rate_hz, part);
        else
            snprintfC(buf, sizeof buf,
                      "%zu,%.6f,%.6f,,,,,%.6f,%.6f,,%" PRId64 ",%" PRId64 ",%" PRId64 ",%" PRId64
                      ",%.9f,%.3f,%.3f,%s\n",
                      index, t, s, p.x_mm, p.a_deg, px, pa, step.x_pulses, step.a_pulses, step.dt_s,
                      step.x_rate_hz, step.a_rate_hz, part);
        out += buf;
        ++index;
        t += step.dt_s;
        s += step.ds_mm;
    };
    const size_t n = cut.points.size();
    for (size_t i = 0; i < leads.lead_in.size(); ++i) {
        const ProfilePoint& p = leads.lead_in[i];
        const std::int64_t px = xPulses(p.x_mm), pa = aPulses(p.a_deg);
        const ProfilePoint& next =
            i + 1 < leads.lead_in.size() ? leads.lead_in[i + 1] : cut.points.front();
        row(p, nullptr, 0, px, pa, stepTo(px, pa, next), "lead_in");
    }
    std::int64_t px = sch.x_start_pulses, pa = sch.a_start_pulses;
    for (size_t i = 0; i <= n; ++i) {
        const ProfilePoint p = cut.closedAt(i);
        const bool closing = i == n;
        PulseStep step = closing || i >= sch.steps.size() ? PulseStep{} : sch.steps[i];
        if (closing && !leads.lead_out.empty()) step = stepTo(px, pa, leads.lead_out.front());
        row(p, &p, closing ? 360.0 : p.beta_deg, px, pa, step, "cut");
        px += step.x_pulses;
        pa += step.a_pulses;
    }
    for (size_t i = 0; i < leads.lead_out.size(); ++i) {
        const ProfilePoint& p = leads.lead_out[i];
        const PulseStep step =
            i + 1 < leads.lead_out.size() ? stepTo(px, pa, leads.lead_out[i + 1]) : PulseStep{};
        row(p, nullptr, 0, px, pa, step, "lead_out");
        px += step.x_pulses;
        pa += step.a_pulses;
    }
    return out;
}

} // namespace cutcell
