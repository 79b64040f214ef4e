#include "core/machines/pipe_robot/cut_simulation.h"

#include "core/control/pid_filter.h"
#include "core/machines/pipe_robot/pipe_robot_mechanics.h"
#include "core/machines/pipe_robot/pipe_robot_program.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

TrackingReport simulateCut(const Job& job, const CutPlan& plan) {
    return simulateCut(job, plan, nullptr);
}

TrackingReport simulateCut(const Job& job, const CutPlan& plan, const CutSampleObserver& onSample) {
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
    const double cruiseFrom = plan.cruise_from_s, cruiseTo = plan.cruise_to_s;
    std::array<PidFilter, kAxisCount> pid;
    PipeRobotMechanics plant(job, T);
    plant.setState(plan.spline.evaluate(0).q);
    // The drives have been holding the start pose: each loop starts with the torque that
    // holds it (gravity, on the rigid-body plant), as a drive releasing its brake does.
    for (int i = 0; i < kAxisCount; ++i) {
        pid[static_cast<size_t>(i)].configure(spec.controller[static_cast<size_t>(i)], T);
        if (!spec.gravity_feedforward) pid[static_cast<size_t>(i)].preload(plant.holdingTorque(i));
    }
    JointVector torque = JointVector::Zero(), applied = JointVector::Zero();
    JointVector gravity = JointVector::Zero();
    const double simulated = std::max(job.sim.duration_s, plan.cut_time_s);
    const long steps = static_cast<long>(std::ceil(simulated / T - 1e-9));
    JointVector actual = JointVector::Zero();
    for (long k = 0; k <= steps; ++k) {
        const double t = static_cast<double>(k) * T;
        const JointVector ref = plan.spline.position(t);
        for (int i = 0; i < kAxisCount; ++i)
            actual[i] = plant.position(i);
        // The tips are computed once and shared by the overall and the cruise figures.
        if (onSample) onSample(t, ref, actual);
        const TipSample tips = stats.tips(ref, actual);
        stats.add(ref, actual, tips);
        if (t >= cruiseFrom && t <= cruiseTo) cruise.add(ref, actual, tips);
        // Optional gravity compensation at the measured pose (off by default, as in the seed).
        if (spec.gravity_feedforward) plant.gravityTorques(actual, gravity);
        for (int i = 0; i < kAxisCount; ++i)
            torque[i] = pid[static_cast<size_t>(i)].step(ref[i] - actual[i]) + gravity[i];
        plant.step(torque, applied);
        for (int i = 0; i < kAxisCount; ++i)
            stats.addTorqueFraction(std::fabs(applied[i]) / plant.torqueLimit(i));
    }
    stats.fill(report);
    cruise.fillCruise(report);
    report.simulated_s = static_cast<double>(steps) * T;
    return report;
}

} // namespace cutcell
