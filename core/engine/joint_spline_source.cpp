#include "core/engine/joint_spline_source.h"

#include <algorithm>

namespace cutcell {

void JointSplineSource::bind(const MotionProgram* program, double feedHoldDecel_s) {
    program_ = program;
    decel_s_ = feedHoldDecel_s;
    startTime_ = 0;
    clock_.restart(0, 0);
}

JointVector JointSplineSource::startPosition() const {
    return program_ ? program_->spline.evaluate(startTime_).q : JointVector::Zero();
}

SourceOutput JointSplineSource::progressAtStart(double overrideFraction) const {
    SourceOutput out;
    describe(startTime_, 0.0, overrideFraction, out); // at the override it will run at
    out.made = 0;                                     // nothing pierced yet
    return out;
}

void JointSplineSource::start(const SourceInput& in) {
    // At path time 0 the spline is at rest: full rate at once (sample 0 is this cycle, as in
    // the offline simulation). A recovered cut starts where the path moves: the rate ramps up
    // from rest, so neither the set-point nor its velocity jumps.
    clock_.restart(startTime_, startTime_ > 0 ? 0.0 : in.override_fraction);
    lastRequest_ = SourceRequest::Run;
}

// Path time, progress, points and the time left of a sample at path time t, at `rate` (the
// override's when at rest).
void JointSplineSource::describe(double t, double rate, double overrideFraction,
                                 SourceOutput& out) const {
    if (!program_) return;
    const double cut = program_->cut_time_s;
    out.program_time_s = t;
    out.progress = cut > 0 ? t / cut : 0;
    out.point_count = static_cast<std::uint32_t>(program_->point_count);
    out.point_index = static_cast<std::uint32_t>(
        std::min<double>(t / program_->spline.dt(), static_cast<double>(program_->point_count)));
    const double r = rate > 0 ? rate : overrideFraction;
    out.remaining_s = r > 0 ? (cut - t) / r : 0;
    out.made = 1; // a path pierces once, where it starts (or resumes)
}

void JointSplineSource::update(const SourceInput& in, SourceOutput& out) {
    lastRequest_ = in.request;
    const double t = clock_.time();
    const double rate = clock_.rate();
    const JointSample s = program_->spline.evaluate(t);
    out.position = s.q;
    out.velocity = s.qd * rate;
    out.acceleration = s.qdd * (rate * rate); // the rate's own change ignored (it ramps slowly)
    describe(t, rate, in.override_fraction, out);
    const bool run = in.request == SourceRequest::Run;
    out.tool_on = run || (in.request == SourceRequest::FeedHold && in.tool_on_during_feed_hold);

    const double target = run ? in.override_fraction : 0.0;
    const double cut = program_->cut_time_s;
    clock_.step(target, in.period_s, in.period_s / decel_s_, cut);
    const double T = in.period_s;
    if (clock_.time() / T >= cut / T - 1e-9)
        out.status = SourceStatus::Done;
    else if (!run && clock_.rate() <= 0)
        out.status = SourceStatus::AtRest;
    else
        out.status = SourceStatus::Working;
}

const char* JointSplineSource::stateName() const {
    if (program_ && clock_.time() >= program_->cut_time_s) return "at the path's end";
    if (clock_.rate() > 0) return "on the path";
    return lastRequest_ == SourceRequest::Run ? "starting on the path" : "held on the path";
}

} // namespace cutcell
