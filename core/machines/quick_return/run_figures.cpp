#include "core/machines/quick_return/run_figures.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace cutcell::quick_return {

RunFigures::RunFigures(const QuickReturnLawConfig& law) : law_(law) {}

void RunFigures::clear() {
    points_.clear();
    hasPrev1_ = hasPrev2_ = false;
    active_ = false;
    dropped_ = 0;
    stroke_ = -1;
    inStroke_ = t0Refined_ = false;
    t0_ = 0;
    strokeFirst_ = 0;
    doneSum_ = doneMax_ = maxTorque_ = 0;
    doneCount_ = cuts_ = 0;
}

bool RunFigures::add(const TelemetrySample& s) {
    const bool run = s.state == EngineState::Running || s.state == EngineState::Paused;
    if (!run) {
        if (active_) flush();
        active_ = false;
        lastWasRun_ = false;
        return false;
    }
    bool began = false;
    if (!lastWasRun_) {
        clear();
        ++runs_;
        active_ = true;
        began = true;
    }
    lastWasRun_ = true;
    const auto a = static_cast<Eigen::Index>(law_.axis);
    const WhitworthPose pose = forwardKinematics(law_.dims, s.actual[a]);
    const WhitworthPose set = forwardKinematics(law_.dims, s.setpoint[a]);
    if (!pose.closes || !std::isfinite(s.elapsed_s)) return began; // not on this mechanism
    Raw cur;
    cur.t = s.elapsed_s;
    cur.y = pose.y + law_.dims.scale_offset;
    cur.torque = s.command[a];
    cur.setpointY = set.closes ? set.y + law_.dims.scale_offset : cur.y;
    cur.cutting =
        std::strncmp(s.source_state.data(), toString(QrPhase::Cut), s.source_state.size()) == 0;
    cur.supervised = s.supervised[static_cast<std::size_t>(law_.axis)];
    if (hasPrev1_ && !(cur.t > prev1_.t)) return began; // a repeated time: nothing new
    if (hasPrev1_) {
        // Central difference at prev1 (backward for the run's first sample).
        const Raw& from = hasPrev2_ ? prev2_ : prev1_;
        push(prev1_, (cur.y - from.y) / (cur.t - from.t));
    }
    prev2_ = prev1_;
    hasPrev2_ = hasPrev1_;
    prev1_ = cur;
    hasPrev1_ = true;
    return began;
}

void RunFigures::flush() {
    if (hasPrev1_) {
        const double dy =
            hasPrev2_ && prev1_.t > prev2_.t ? (prev1_.y - prev2_.y) / (prev1_.t - prev2_.t) : 0;
        push(prev1_, dy);
    }
    hasPrev1_ = hasPrev2_ = false;
    if (inStroke_) finishStroke();
}

void RunFigures::push(const Raw& r, double dy) {
    if (r.cutting && !inStroke_) {
        inStroke_ = true;
        t0Refined_ = false;
        t0_ = r.t; // the law restarts its profile in the cycle it enters the cut
        ++stroke_;
        ++cuts_;
        strokeFirst_ = points_.size();
    } else if (!r.cutting && inStroke_) {
        finishStroke();
    }
    const VelocityProfile& pr = law_.profile;
    bool refined = false;
    if (r.cutting && r.supervised && !t0Refined_ && pr.ok && pr.v != 0) {
        // Supervised: the set-point is the profile's y_d on its constant-velocity part.
        t0_ = r.t - (pr.t_a + (r.setpointY - pr.y_a) / pr.v);
        t0Refined_ = refined = true;
    }
    RunFigurePoint p;
    p.t = r.t;
    p.y = r.y;
    p.dy = dy;
    p.torque = r.torque;
    p.cutting = r.cutting;
    p.stroke = r.cutting ? stroke_ : -1;
    p.y_d = r.y;
    const double lo = std::min(pr.y_a, pr.y_b), hi = std::max(pr.y_a, pr.y_b);
    p.in_work = r.cutting && r.y >= lo && r.y <= hi;
    maxTorque_ = std::max(maxTorque_, std::fabs(r.torque));
    points_.push_back(p);
    if (refined)
        refreshStroke();
    else if (r.cutting)
        refreshPoint(points_.back());
    if (points_.size() > kMaxPoints) {
        // Drop the oldest points, never those of the stroke in progress.
        std::size_t drop = points_.size() - kMaxPoints * 3 / 4;
        if (inStroke_) drop = std::min(drop, strokeFirst_);
        points_.erase(points_.begin(), points_.begin() + static_cast<std::ptrdiff_t>(drop));
        if (inStroke_) strokeFirst_ -= drop;
        dropped_ += drop;
    }
}

void RunFigures::refreshPoint(RunFigurePoint& p) const {
    const ProfileSample s = sampleProfile(law_.profile, p.t - t0_);
    p.y_d = s.y;
    p.dy_d = s.dy;
}

void RunFigures::refreshStroke() {
    for (std::size_t i = strokeFirst_; i < points_.size(); ++i)
        refreshPoint(points_[i]);
}

void RunFigures::accumulate(std::size_t from, double* sum, int* n, double* max) const {
    for (std::size_t i = from; i < points_.size(); ++i) {
        const RunFigurePoint& p = points_[i];
        if (!p.in_work || !std::isfinite(p.dy)) continue;
        const double e = p.dy_d - p.dy;
        *sum += e * e;
        ++*n;
        *max = std::max(*max, std::fabs(e));
    }
}

void RunFigures::finishStroke() {
    accumulate(strokeFirst_, &doneSum_, &doneCount_, &doneMax_);
    inStroke_ = false;
}

RunFigureStats RunFigures::stats() const {
    double sum = doneSum_, max = doneMax_;
    int n = doneCount_;
    if (inStroke_) accumulate(strokeFirst_, &sum, &n, &max);
    RunFigureStats s;
    s.cuts = cuts_;
    s.samples_in_work = n;
    s.velocity_error_max = max;
    s.velocity_error_rms = n > 0 ? std::sqrt(sum / n) : 0;
    s.max_torque = maxTorque_;
    return s;
}

} // namespace cutcell::quick_return
