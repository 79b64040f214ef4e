#pragma once
// Offline fixed-step simulation of a planned cut: per axis the PID with first-order filter
// drives the joint plant toward the spline's set-point at the control period.
#include "core/job/job.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/sim/tracking_stats.h"

#include <functional>

namespace cutcell {

// Simulated time: the longer of sim.duration_s and the cut itself.
TrackingReport simulateCut(const Job& job, const CutPlan& plan);
// The same, calling onSample(t, commanded, actual) every cycle after the axes are sampled.
using CutSampleObserver =
    std::function<void(double t, const JointVector& commanded, const JointVector& actual)>;
TrackingReport simulateCut(const Job& job, const CutPlan& plan, const CutSampleObserver& onSample);

} // namespace cutcell
