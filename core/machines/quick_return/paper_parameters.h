#pragma once
// Seed 004's experiment 1 with the paper's own masses and gains, and what to look for in it:
//   - the figures the seed prints for its prototype (below, each with where it is printed) and
//     a spec that takes them over the project's plant (paperParameters); the printed mechanism
//     does not close (README, errata), so the mechanism, the crank's inertias and friction,
//     the gains the seed does not print (LQT Q, R; SMC c, eta, phi; OSMC Q, lambda), K_rho and
//     the sample time stay the project's (job resources/jobs/quick_return_paper_job.json);
//   - a limit-cycle detector: a sustained oscillation of a signal (the tracking error, the
//     sliding variable) at a frequency that is not one of the inputs' (reference, disturbance)
//     nor a harmonic of them, whose amplitude does not decay over the last seconds;
//   - the experiment-1 study: the four controllers with the detector on their errors, and a
//     sweep of the OSMC's k2 at the job's k1 for the smallest k2 whose MSE beats FFC and LQT.
// `cutcell-cli simulate` prints the study for a job whose control.experiment is "tracking".
#include "core/machines/quick_return/experiments.h"
#include "core/machines/quick_return/quick_return_spec.h"

#include <span>
#include <string>
#include <vector>

namespace cutcell::quick_return {

// The seed's printed figures (seed 004, Sec. 6 "Experimental results").
// m5: Sec. 6.1, after Eq. 35 ("The slider mass is m5 = 4.5 x 10^-4 kg"); Eq. 36 agrees
// (b = 2222.22 = 1/m5, m5 g = 0.00441 N).
inline constexpr double kPaperSliderMass = 4.5e-4; // kg
// FFC: Sec. 6.1 after Eq. 38 ("omega_n^2 = 1000 and xi = 1").
inline constexpr double kPaperFfcWn2 = 1000, kPaperFfcXi = 1;
// OSMC (27): Sec. 6.2 ("The gains of the OSMC (27) were k1 = 40 and k2 = 1"; the hyperplane is
// "the gain obtained in the last section", not printed).
inline constexpr double kPaperOsmcK1 = 40, kPaperOsmcK2 = 1;
// MSE: Sec. 6.1 ("the last 2 seconds", "L = 100").
inline constexpr double kPaperMseScale = 100, kPaperMseWindow = 2; // 1, s

// base with the seed's printed masses and gains: the slider's mass in the plant and in the
// controllers' model (m5), FFC's omega_n^2 and xi, the OSMC's k1 and k2, the MSE's L and window;
// experiment 1 (tracking). Everything else is base's.
QuickReturnSpec paperParameters(QuickReturnSpec base);

struct LimitCycleOptions {
    double window_s = 4;           // the last seconds of the signal analysed
    std::vector<double> forced_hz; // the inputs' frequencies (reference, disturbance), Hz
    int forced_harmonics = 20;     // removed (least squares) with their harmonics up to this
    double min_cycles = 4;         // the period: at most window / min_cycles
    double min_periodicity = 0.5;  // the autocorrelation's peak at the period: at least this
    double sustain_ratio = 0.8;    // amplitude over the late half / early half: at least this
    // The late amplitude must exceed min_amplitude + min_amplitude_per_hz * frequency (signal's
    // unit): a floor such as the sensor's resolution, or its rate at the frequency.
    double min_amplitude = 0, min_amplitude_per_hz = 0;
};

struct LimitCycle {
    bool detected = false;
    double frequency_hz = 0; // 1 / the period
    double periodicity = 0;  // normalised autocorrelation at the period (1: exactly periodic)
    // Sinusoid-equivalent amplitudes sqrt(2) rms of the residual (signal's unit) over the window
    // and over its first and second half.
    double amplitude = 0, amplitude_early = 0, amplitude_late = 0;
    std::string verdict; // what was found, and why it is (not) a limit cycle
    double ratio() const { return amplitude_early > 0 ? amplitude_late / amplitude_early : 0; }
};

// The detector on x sampled every dt seconds (its last window_s seconds). The residual: x less
// its mean, a linear drift and the forced tones with their harmonics (least squares). Its period:
// the lag of the highest peak of its autocorrelation past the first zero crossing, between two
// samples and window / min_cycles, not at a forced frequency (parabolic between the lags). A
// limit cycle: the residual is periodic (the peak at least min_periodicity of the zero lag), its
// late amplitude is above the floor and at least sustain_ratio of its early one. The shape of
// the oscillation does not matter (a relay's square wave, a whirling crank's strokes).
LimitCycle detectLimitCycle(std::span<const double> x, double dt, const LimitCycleOptions& o);

// The detector's options for experiment 1 of a set-up: the reference's and the disturbance's
// frequencies forced (with 20 harmonics: the mechanism is not linear, and the disturbance's
// effect is modulated by the reference's motion, 3 +- k 0.5 Hz), the last 4 s (two periods of
// the seed's reference; at most half the run).
LimitCycleOptions experiment1CycleOptions(const ExperimentSetup& s);

struct Experiment1Run {
    ControllerKind controller = ControllerKind::Osmc;
    double k2 = 0; // the OSMC's (the sweep's point)
    double mse = 0, max_abs_error = 0, max_torque = 0;
    LimitCycle error_cycle;   // of e = y_d - y (m)
    LimitCycle sliding_cycle; // of s / c2 = slope e + e' (m/s), the OSMC's surface
    // Over the detector's window: the crank's passes through its singular points (0 while the
    // slider stays on the cutting branch, as the reference does) and its net turns.
    int singular_passes = 0;
    double crank_turns = 0;
};

struct K2Sweep {
    double from = 0.1, to = 1000; // N (k2's unit in the job)
    int points = 21;              // log-spaced, both ends included (5 a decade)
    int refine_steps = 5;         // bisections (log k2) between the last loser and first winner
};

struct Experiment1Study {
    std::vector<Experiment1Run> runs; // the four controllers with the set-up's gains
    double k1 = 0;                    // the OSMC's, held in the sweep
    double rival_mse = 0;             // min(MSE of FFC, MSE of LQT)
    std::vector<Experiment1Run> sweep;
    bool osmc_wins = false;    // some k2 of the sweep beats FFC and LQT
    double smallest_k2 = 0;    // the sweep's smallest winning k2
    double threshold_lo = 0;   // the refined threshold: loses at lo, wins at hi
    double threshold_hi = 0;   // (both smallest_k2 when the sweep's first point wins)
    std::string sweep_skipped; // why the sweep was not run (over max_samples)
};

// Experiment 1 of s for the four controllers and the k2 sweep (skipped with the reason when
// its samples would exceed max_samples).
Experiment1Study studyExperiment1(const ExperimentSetup& s, const K2Sweep& sweep,
                                  double max_samples);

} // namespace cutcell::quick_return
