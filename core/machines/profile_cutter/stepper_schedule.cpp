#include "core/machines/profile_cutter/stepper_schedule.h"
#include "core/common/c_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cutcell {

PulseSchedule buildPulseSchedule(const ProfileCut& cut, const ProfileCutterSpec& spec,
                                 double speed_mm_s) {
    PulseSchedule s;
    s.mm_per_pulse_x = spec.mm_per_pulse_x;
    s.deg_per_pulse_a =
        360.0 / (static_cast<double>(spec.steps_per_rev_a) * spec.pulses_per_step_a);
    const double radPerPulse = deg2rad(s.deg_per_pulse_a);
    auto xPulses = [&](double x) {
        return static_cast<std::int64_t>(std::llround(x / s.mm_per_pulse_x));
    };
    auto aPulses = [&](double a) {
        return static_cast<std::int64_t>(std::llround(a / s.deg_per_pulse_a));
    };
    const size_t n = cut.points.size();
    if (n == 0) return s;
    s.x_start_pulses = xPulses(cut.points.front().x_mm);
    s.a_start_pulses = aPulses(cut.points.front().a_deg);
    s.steps.reserve(n);
    std::int64_t px = s.x_start_pulses, pa = s.a_start_pulses;
    for (size_t i = 0; i < n; ++i) {
        const ProfilePoint next = cut.closedAt(i + 1);
        const std::int64_t nx = xPulses(next.x_mm), na = aPulses(next.a_deg);
        PulseStep st;
        st.x_pulses = nx - px;
        st.a_pulses = na - pa;
        st.ds_mm = std::hypot(static_cast<double>(st.x_pulses) * s.mm_per_pulse_x,
                              cut.work_radius_mm * static_cast<double>(st.a_pulses) * radPerPulse);
        // A step in which neither motor moves takes no time.
        st.dt_s = st.ds_mm / speed_mm_s;
        if (st.dt_s > 0) {
            st.x_rate_hz = static_cast<double>(std::llabs(st.x_pulses)) / st.dt_s;
            st.a_rate_hz = static_cast<double>(std::llabs(st.a_pulses)) / st.dt_s;
        }
        s.total_time_s += st.dt_s;
        s.developed_length_mm += st.ds_mm;
        s.max_x_rate_hz = std::max(s.max_x_rate_hz, st.x_rate_hz);
        s.max_a_rate_hz = std::max(s.max_a_rate_hz, st.a_rate_hz);
        if (s.problem.empty() && std::max(st.x_rate_hz, st.a_rate_hz) > spec.max_pulse_rate_hz) {
            s.problem = messageC("step %zu (beta = %.3f deg) needs %.0f Hz on the %s axis, above "
                                 "machine.profile_cutter.max_pulse_rate_hz = %.0f Hz: lower "
                                 "cut.speed_mm_s",
                                 i, cut.points[i].beta_deg, std::max(st.x_rate_hz, st.a_rate_hz),
                                 st.x_rate_hz >= st.a_rate_hz ? "X" : "A", spec.max_pulse_rate_hz);
        }
        s.steps.push_back(st);
        px = nx;
        pa = na;
    }
    return s;
}

} // namespace cutcell
