#pragma once
// Offline fixed-step simulation of a planned cut: per axis the PID with first-order filter
// drives the joint plant toward the spline's set-point at the control period.
#include "core/job/job.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/sim/tracking_stats.h"

namespace cutcell {

// Simulated time: the longer of sim.duration_s and the cut itself.
TrackingReport simulateCut(const Job& job, const CutPlan& plan);

} // namespace cutcell
