#pragma once
// The cutting experiment's figures of a run on the engine, from its telemetry (not a
// re-simulation): the slider's position y, velocity y', the reference y_d, y_d' and the crank
// torque over time, and the velocity error y_d' - y' while the slider is over the workpiece
// (between y_a and y_b) in a cutting stroke, with its max and RMS, as the offline experiment
// (experiments.h, runCutting) counts them.
//
// From each telemetry sample: y = FK(crank angle actual[axis]) + scale_offset (the encoder's
// angle through B.2, not the scale's 85 um steps); y' the central difference of consecutive
// samples' y (2 ms wide at telemetry every cycle; wider when the telemetry is decimated, e.g.
// the fast clock's every 10th cycle); the cutting stroke is the law's state "cutting stroke"
// (source_state); y_d, y_d' Algorithm 1's profile from the stroke's start. The start is the
// first cutting sample's time, refined by the first supervised sample: there the law's crank
// set-point maps to the profile's y_d on its constant-velocity part, which tells the time since
// the stroke began exactly, also when the telemetry skips cycles.
//
// A run starts with a Running sample after any other state; Running and Paused samples count;
// any other state (Completed, EmergencyStop, Fault, ...) ends it. Pure C++, no allocation limits
// beyond kMaxPoints (the oldest finished strokes' points are dropped; the figures keep counting).
#include "core/engine/engine_types.h"
#include "core/machines/quick_return/quick_return_law.h"

#include <cstdint>
#include <vector>

namespace cutcell::quick_return {

struct RunFigurePoint {
    double t = 0; // s since Start (telemetry elapsed_s)
    double y = 0, dy = 0;
    double y_d = 0, dy_d = 0; // the profile's; y, 0 outside a cutting stroke
    double torque = 0;        // N m, the crank's command
    bool cutting = false;     // in a cutting stroke (the law's state)
    bool in_work = false;     // cutting with y between y_a and y_b
    int stroke = -1;          // 0-based cutting stroke, -1 outside
};

struct RunFigureStats {
    int cuts = 0; // cutting strokes begun
    int samples_in_work = 0;
    double velocity_error_max = 0; // m/s, |y_d' - y'| over the workpiece
    double velocity_error_rms = 0;
    double max_torque = 0; // N m
};

class RunFigures {
  public:
    static constexpr std::size_t kMaxPoints = 400000; // ~7 min of telemetry at 1 kHz

    explicit RunFigures(const QuickReturnLawConfig& law);
    // The law of the next run (the figures so far are kept until it starts).
    void setLaw(const QuickReturnLawConfig& law) { law_ = law; }

    void clear();
    // One telemetry sample, oldest first. Returns true when it began a new run.
    bool add(const TelemetrySample& s);
    // Ends the pending sample as the last of the run (done by add() for a non-run state).
    void flush();

    bool active() const { return active_; } // within a run (Running or Paused)
    // The last sample was of a run: a Running sample now continues it (else it begins one).
    bool lastWasRun() const { return lastWasRun_; }
    std::uint64_t runs() const { return runs_; } // runs begun since construction
    const std::vector<RunFigurePoint>& points() const { return points_; }
    std::uint64_t droppedPoints() const { return dropped_; }
    RunFigureStats stats() const;
    const QuickReturnLawConfig& law() const { return law_; }

  private:
    struct Raw {
        double t = 0, y = 0, torque = 0, setpointY = 0;
        bool cutting = false, supervised = false;
    };
    void push(const Raw& r, double dy); // (not "emit": a Qt macro)
    void finishStroke();
    void refreshPoint(RunFigurePoint& p) const; // y_d, y_d' from t0_
    void refreshStroke();                       // of the current stroke's points
    // The velocity error of the points from `from` on (in the work only).
    void accumulate(std::size_t from, double* sum, int* n, double* max) const;

    QuickReturnLawConfig law_;
    std::vector<RunFigurePoint> points_;
    Raw prev2_, prev1_;
    // prev1_: the last sample, emitted when the next one gives its central difference;
    // prev2_: the one before (emitted).
    bool hasPrev1_ = false, hasPrev2_ = false;
    bool active_ = false, lastWasRun_ = false;
    std::uint64_t runs_ = 0, dropped_ = 0;
    // The current cutting stroke.
    int stroke_ = -1;
    bool inStroke_ = false, t0Refined_ = false;
    double t0_ = 0;
    std::size_t strokeFirst_ = 0; // index in points_ of the stroke's first point
    // Finished strokes.
    double doneSum_ = 0, doneMax_ = 0, maxTorque_ = 0;
    int doneCount_ = 0, cuts_ = 0;
};

} // namespace cutcell::quick_return
