#include "core/machines/pipe_robot/cut_simulation.h"

#include "core/control/joint_plant.h"
#include "core/control/pid_filter.h"
#include "core/machines/pipe_robot/pipe_robot_program.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

TrackingReport simulateCut(const Job& job, const CutPlan& plan) {
    const PipeRobotSpec& spec = pipeRobotSpec(job);
    TrackingReport report;
    report.axis_count = kAxisCount;
    report.method = toString(spec.method);
    report.reachable = plan.reachable;
    report.problem = plan.problem;
    report.length_mm = plan.length_mm;
    report.cut_time_s = plan.cut_time_s;
    report.max_direction_deviation_deg = plan.max_deviation_deg;

    const double T = job.sim.period_s;
    const PipeRobotTipModel tipModel(spec.dh);
    TrackingStats stats(&tipModel);
    TrackingStats cruise(&tipModel);
    const SpeedProfile profile(plan.length_mm, job.cut.speed_mm_s, job.cut.ramp_s);
    const double ramp = (profile.duration() - plan.length_mm / job.cut.speed_mm_s);
    const double cruiseFrom = ramp, cruiseTo = plan.cut_time_s - ramp;
    std::array<PidFilter, kAxisCount> pid;
    std::array<JointPlant, kAxisCount> plant;
    const JointSample start = plan.spline.evaluate(0);
    for (int i = 0; i < kAxisCount; ++i) {
        pid[static_cast<size_t>(i)].configure(spec.controller[static_cast<size_t>(i)], T);
        plant[static_cast<size_t>(i)].configure(spec.plant[static_cast<size_t>(i)], T);
        plant[static_cast<size_t>(i)].setState(start.q[i], 0);
    }
    const double simulated = std::max(job.sim.duration_s, plan.cut_time_s);
    const long steps = static_cast<long>(std::ceil(simulated / T - 1e-9));
    JointVector actual = JointVector::Zero();
    for (long k = 0; k <= steps; ++k) {
        const double t = static_cast<double>(k) * T;
        const JointVector ref = plan.spline.position(t);
        for (int i = 0; i < kAxisCount; ++i)
            actual[i] = plant[static_cast<size_t>(i)].position();
        // The tips are computed once and shared by the overall and the cruise figures.
        const TipSample tips = stats.tips(ref, actual);
        stats.add(ref, actual, tips);
        if (t >= cruiseFrom && t <= cruiseTo) cruise.add(ref, actual, tips);
        for (int i = 0; i < kAxisCount; ++i) {
            const size_t a = static_cast<size_t>(i);
            const double u = plant[a].step(pid[a].step(ref[i] - actual[i]));
            stats.addTorqueFraction(std::fabs(u) / plant[a].torqueLimit());
        }
    }
    stats.fill(report);
    cruise.fillCruise(report);
    report.simulated_s = static_cast<double>(steps) * T;
    return report;
}

} // namespace cutcell
