#pragma once
// A simple control law run in the engine cycle (the reference law of the ControlLaw source and
// its tests): one torque-mode axis (a slider driven by a force, N) closed on an external linear
// position sensor, with the shape of a quick-return cutter (seed 004):
//   Stroke   closed loop: the reference runs from stroke_from to stroke_to at stroke_speed
//            (times the override); F = kp (x_ref - x) + kd (v_ref - v), supervised;
//   Return   open loop: a constant force return_force drives the slider back until it passes
//            stroke_from + catch_distance; no position reference, so following error is NOT
//            supervised (reason in the event);
//   Catch    closed loop to stroke_from (supervised again once within catch_window), then the
//            next stroke, until stroke_count strokes are done (Done, holding at stroke_from).
// Track (hold / home / approach): PD on the engine's set-point. FeedHold, Abort and a
// controlled stop: the reference freezes where the slider is and the PD brakes it; AtRest once
// |v| < rest_speed for rest_cycles cycles (an open-loop return is first caught: it cannot be
// stopped in the middle without a reference). A sensor reading that is not valid is a fault:
// the law commands no force and the engine removes torque.
#include "core/engine/motion_source.h"

namespace cutcell {

struct PdSliderLawConfig {
    int axis = 0;                                                // the torque-mode axis
    int sensor = 0;                                              // its linear position sensor
    double kp = 50, kd = 1;                                      // N/mm, N s/mm
    double force_limit = 500;                                    // N
    double stroke_from = 0, stroke_to = 200, stroke_speed = 100; // mm, mm/s
    double return_force = -50;                                   // N
    double catch_distance = 40, catch_window = 0.5;              // mm
    int stroke_count = 2;
    double rest_speed = 0.05; // mm/s
    int rest_cycles = 20;
};

enum class SliderPhase : std::uint8_t { Track, Stroke, Return, Catch, Braking, Done };
const char* toString(SliderPhase p);

class PdSliderLaw : public MotionSource {
  public:
    explicit PdSliderLaw(const PdSliderLawConfig& config) : cfg_(config) {}
    void start(const SourceInput& in) override;
    void update(const SourceInput& in, SourceOutput& out) override;
    const char* stateName() const override { return toString(phase_); }
    SliderPhase phase() const { return phase_; }
    int strokesDone() const { return strokes_; }

  private:
    double pd(double xRef, double vRef, double x, double v) const;
    PdSliderLawConfig cfg_;
    SliderPhase phase_ = SliderPhase::Track;
    double ref_ = 0, brakeAt_ = 0;
    int strokes_ = 0, restCount_ = 0;
    bool caught_ = false;
};

} // namespace cutcell
