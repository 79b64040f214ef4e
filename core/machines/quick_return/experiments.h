#pragma once
// The two experiments of seed 004 offline: the crank plant (crank_plant.h) stepped at the
// sample time under the very control law the engine runs (quick_return_law.h), the slider
// read through a scale of the given resolution.
//   1. tracking y_d = -0.2 - 0.2 sin(pi t) without contact force; MSE of the last 2 s with
//      the scale factor L: mean((L e_i)^2);
//   2. the cutting task over several strokes with the 400 N contact force: velocity error
//      y_d' - y' while the slider is over the workpiece ([y_b, y_a]), its max and RMS.
#include "core/machines/quick_return/crank_plant.h"
#include "core/machines/quick_return/quick_return_law.h"

#include <string>
#include <vector>

namespace cutcell::quick_return {

struct ExperimentSetup {
    QuickReturnLawConfig law; // experiment, controller and gains set by the runners
    CrankPlantParams plant;
    double sample_time = 0.001;          // s
    double scale_resolution = 8.4667e-5; // m (300 counts per inch)
    double disturbance_amplitude = 0.2;  // N m, sinusoidal torque on the crank
    double disturbance_hz = 3;
    double mse_window = 2;    // s
    double mse_scale = 100;   // L
    int trace_every = 10;     // samples kept for plots (every n-th)
    bool keep_errors = false; // runTracking: the true errors of every sample (limit cycles)
};

struct TracePoint {
    double t, y, dy, y_d, dy_d, torque;
    bool cutting;
};

struct TrackingResult {
    ControllerKind controller = ControllerKind::Osmc;
    double mse = 0;           // of L e over the last mse_window seconds
    double max_abs_error = 0; // m, over the same window
    double max_torque = 0;    // N m
    std::vector<TracePoint> trace;
    // With ExperimentSetup::keep_errors, every sample's e = y_d - y and e' = y_d' - y' of the
    // true slider (the plant's, not the scale's), as the MSE takes them, and the crank (rad).
    std::vector<double> error, error_rate, crank;
};

struct CuttingResult {
    ControllerKind controller = ControllerKind::Osmc;
    bool completed = false;
    std::string problem; // why not (fault, time-out)
    int strokes = 0;
    double velocity_error_max = 0; // m/s, |y_d' - y'| over the workpiece
    double velocity_error_rms = 0;
    int samples_in_work = 0;
    double max_torque = 0;  // N m
    double cycle_time = 0;  // s, from the first cut start to the last one (mean per stroke)
    double return_time = 0; // s, mean open-loop return
    std::vector<TracePoint> trace;
};

TrackingResult runTracking(const ExperimentSetup& setup, ControllerKind controller);
CuttingResult runCutting(const ExperimentSetup& setup, ControllerKind controller);

} // namespace cutcell::quick_return
