#pragma once
// The joint spline in time as a motion source (MotionSourceKind::JointSpline: the pipe robot,
// the profile cutter, the section steel): the set-point is the program's spline at the path
// time, which advances by the path rate each cycle. Feed hold, abort and a controlled stop
// ramp the rate to 0, override ramps it to the new fraction, at 1 / feed_hold_decel_s per
// second, so neither the set-point nor its velocity jumps. The only source that can resume a
// cut at a path time (cut recovery).
//
// Like the offline simulation, each update() samples the path at its current time and then
// steps the time with this cycle's request; so its status speaks of the next sample (Done: the
// path's end is reached, AtRest: the rate is 0), which the engine reads at its next cycle.
#include "core/engine/motion_program.h"
#include "core/engine/motion_source.h"
#include "core/engine/path_clock.h"

namespace cutcell {

class JointSplineSource final : public MotionSource {
  public:
    // Outside a run (the engine's Load): the program's spline and the rate's ramp time.
    void bind(const MotionProgram* program, double feedHoldDecel_s);
    // Where the next start() begins: 0, or a cut recovery's path time.
    void setStartTime(double t) { startTime_ = t; }
    // The set-point at the start time (the approach's target).
    JointVector startPosition() const;
    // The run's progress before its first update: where it will start.
    SourceOutput progressAtStart(double overrideFraction) const;

    void start(const SourceInput& in) override;
    void update(const SourceInput& in, SourceOutput& out) override;
    const char* stateName() const override;
    bool resumesInTime() const override { return true; }

  private:
    void describe(double t, double rate, double overrideFraction, SourceOutput& out) const;

    const MotionProgram* program_ = nullptr;
    double decel_s_ = 1;
    double startTime_ = 0;
    PathClock clock_;
    SourceRequest lastRequest_ = SourceRequest::Run;
};

} // namespace cutcell
