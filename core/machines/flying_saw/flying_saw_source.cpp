#include "core/machines/flying_saw/flying_saw_source.h"

#include <algorithm>

namespace cutcell {

const char* toString(SawPhase p) {
    switch (p) {
    case SawPhase::Waiting:
        return "waiting";
    case SawPhase::Accelerating:
        return "synchronizing";
    case SawPhase::InSync:
        return "in sync";
    case SawPhase::Decelerating:
        return "decelerating";
    case SawPhase::Returning:
        return "returning";
    case SawPhase::Stopping:
        return "stopping";
    case SawPhase::Recovering:
        return "recovering";
    case SawPhase::Done:
        return "done";
    }
    return "?";
}

int PieceQueue::total() const {
    int n = 0;
    for (int i = 0; i < size; ++i)
        n += entries[static_cast<size_t>(i)].count;
    return n;
}

namespace {
double smooth5(double u) {
    u = std::clamp(u, 0.0, 1.0);
    return u * u * u * (10 - 15 * u + 6 * u * u);
}
} // namespace

FlyingSawSource::FlyingSawSource(const FlyingSawConfig& config)
    : cfg_(config), filter_(config.filter_alpha) {
    current_ = config.queue;
    total_ = current_.total();
}

bool FlyingSawSource::bladeInWall() const {
    return phase_ == SawPhase::InSync && cfg_.saw.cutting(tauNow_);
}

void FlyingSawSource::reportGauge(int piece, double measured_mm) {
    gaugePiece_.store(piece, std::memory_order_relaxed);
    gaugeMeasured_.store(measured_mm, std::memory_order_relaxed);
    gaugeSeq_.fetch_add(1, std::memory_order_release);
}

void FlyingSawSource::takeGauge() {
    const std::uint64_t seq = gaugeSeq_.load(std::memory_order_acquire);
    if (seq == gaugeTaken_) return;
    gaugeTaken_ = seq;
    const int piece = gaugePiece_.load(std::memory_order_relaxed);
    const double measured = gaugeMeasured_.load(std::memory_order_relaxed);
    if (piece < 1 || piece > committed_ || committed_ - piece >= kRing) return;
    const double pitch = pitch_[ring(piece)];
    if (!(pitch > 0) || !(measured > 0) || !std::isfinite(measured)) return;
    // The true mm per master unit of that piece: (measured + kerf) / pitch; the scale (master
    // units per mm) that would have made it right is its inverse.
    const double target = pitch / (measured + cfg_.kerf_mm);
    scale_ += cfg_.gauge_gain * (target - scale_);
}

bool FlyingSawSource::nextPiece(double* length) {
    if (queue_.takePublished()) {
        current_ = queue_.front();
        entry_ = entryDone_ = 0;
        total_ = committed_ + current_.total();
    }
    while (entry_ < current_.size &&
           entryDone_ >= current_.entries[static_cast<size_t>(entry_)].count) {
        ++entry_;
        entryDone_ = 0;
    }
    if (entry_ >= current_.size) return false;
    *length = current_.entries[static_cast<size_t>(entry_)].length_mm;
    ++entryDone_;
    return true;
}

void FlyingSawSource::start(const SourceInput& in) {
    const SensorReading& r = (*in.sensors)[static_cast<size_t>(cfg_.master_sensor)];
    filter_.reset(r.position, r.valid ? r.velocity : 0);
    phase_ = SawPhase::Waiting;
    firstSync_ = std::isnan(cfg_.first_sync) ? r.position + cfg_.forward.d1 + cfg_.first_sync_lead
                                             : cfg_.first_sync;
    sync_ = firstSync_;
    cut_ = -1;
    cutsDone_ = committed_ = 0;
    entry_ = entryDone_ = 0;
    atRest_ = true;
    restAfterReturn_ = false;
    turnBase_ = in.setpoint[1];
    pos_ = in.setpoint;
    vel_.setZero();
    tauNow_ = 0;
}

void FlyingSawSource::beginRecover(const SourceInput& in) {
    recFrom_ = pos_;
    recTo_ = pos_;
    recTo_[0] = cfg_.wait_position_mm;
    recTo_[1] = kPi * std::ceil(pos_[1] / kPi - 1e-9); // the next half turn: blades aligned
    recTo_[2] = recTo_[3] = 0;
    recSince_ = in.now_s;
    phase_ = SawPhase::Recovering;
}

void FlyingSawSource::update(const SourceInput& in, SourceOutput& out) {
    const double T = in.period_s;
    const SensorReading& r = (*in.sensors)[static_cast<size_t>(cfg_.master_sensor)];
    out.point_count = static_cast<std::uint32_t>(total_);
    if (!r.valid || !std::isfinite(r.position)) {
        out.position = pos_;
        out.velocity.setZero();
        out.status = SourceStatus::Fault;
        out.fault = "line encoder: reading not valid";
        return;
    }
    const double m = filter_.update(r.position, T, r.age_cycles);
    out.master_position = m;
    takeGauge();
    const JointVector prev = pos_;
    const SourceRequest req = in.request;
    const bool leave = req == SourceRequest::Abort || req == SourceRequest::ControlledStop;
    const bool moving = phase_ == SawPhase::Accelerating || phase_ == SawPhase::InSync ||
                        phase_ == SawPhase::Decelerating || phase_ == SawPhase::Returning ||
                        phase_ == SawPhase::Recovering;
    if (leave && moving) {
        phase_ = SawPhase::Stopping;
        decelRate_ = vel_.cwiseAbs() / std::max(cfg_.decel_s, T);
    }
    if (req == SourceRequest::FeedHold && moving) restAfterReturn_ = true;
    const double xSync = carriageSyncPosition();

    switch (phase_) {
    case SawPhase::Waiting: {
        pos_[0] = cfg_.wait_position_mm;
        pos_[2] = pos_[3] = 0;
        if (req != SourceRequest::Run) {
            atRest_ = true;
            break;
        }
        if (atRest_) {
            atRest_ = false;
            if (cut_ < 0 && m > sync_ - cfg_.forward.d1) {
                out.status = SourceStatus::Fault;
                out.fault = "the line is already past the sync-in of the first cut";
                return;
            }
            // Resumed: the next sync position still ahead (the piece in between comes out long).
            double L = 0;
            while (cut_ >= 0 && m > sync_ - cfg_.forward.d1) {
                if (!nextPiece(&L)) break;
                ++committed_;
                ordered_[ring(committed_)] = L;
                pitch_[ring(committed_)] = (L + cfg_.kerf_mm) * scale_;
                sync_ += pitch_[ring(committed_)];
            }
        }
        if (m < sync_ - cfg_.forward.d1) break;
        if (m > sync_) {
            out.status = SourceStatus::Fault;
            out.fault = "the line passed the sync position before the carriage started";
            return;
        }
        phase_ = SawPhase::Accelerating;
        ++cut_;
        [[fallthrough]];
    }
    case SawPhase::Accelerating: {
        const double u = m - (sync_ - cfg_.forward.d1);
        pos_[0] = cfg_.wait_position_mm + cfg_.forward.accel(u);
        if (m < sync_) break;
        phase_ = SawPhase::InSync;
        // The time the master crossed S (interpolated within this cycle).
        const double vm = std::max(filter_.velocity(), 1e-9);
        tSync_ = in.now_s - std::min((m - sync_) / vm, T);
        [[fallthrough]];
    }
    case SawPhase::InSync: {
        pos_[0] = xSync + (m - sync_);
        tauNow_ = in.now_s - tSync_;
        double theta = 0, feed = 0;
        cfg_.saw.at(tauNow_, &theta, &feed);
        pos_[1] = turnBase_ + theta;
        pos_[2] = pos_[3] = feed;
        if (tauNow_ < cfg_.saw.duration()) break;
        pos_[1] = turnBase_ + kPi;
        pos_[2] = pos_[3] = 0;
        phase_ = SawPhase::Decelerating;
        mE_ = m;
        xE_ = pos_[0];
        break;
    }
    case SawPhase::Decelerating: {
        const double u = m - mE_;
        pos_[0] = xE_ + cfg_.forward.decel(u);
        if (u < cfg_.forward.d3) break;
        xF_ = xE_ + cfg_.forward.d3 / 2;
        pos_[0] = xF_;
        reverse_ = fastestReverse(xF_ - cfg_.wait_position_mm, cfg_.limits);
        tF_ = in.now_s;
        phase_ = SawPhase::Returning;
        break;
    }
    case SawPhase::Returning: {
        const double t = in.now_s - tF_;
        pos_[0] = xF_ - reverse_.travel(t);
        if (t < reverse_.duration()) break;
        pos_[0] = cfg_.wait_position_mm; // exactly: travel(duration) == distance
        turnBase_ += kPi;
        ++cutsDone_;
        double L = 0;
        if (cutsDone_ > committed_ && nextPiece(&L)) {
            ++committed_;
            ordered_[ring(committed_)] = L;
            pitch_[ring(committed_)] = (L + cfg_.kerf_mm) * scale_;
            sync_ += pitch_[ring(committed_)];
            phase_ = SawPhase::Waiting;
            atRest_ = restAfterReturn_;
            restAfterReturn_ = false;
            if (!atRest_ && m > sync_ - cfg_.forward.d1) {
                out.status = SourceStatus::Fault;
                out.fault = "the piece is too short for the cycle at this line speed: the next "
                            "sync-in has begun before the carriage was back";
                return;
            }
        } else {
            phase_ = SawPhase::Done;
        }
        break;
    }
    case SawPhase::Stopping: {
        bool still = true;
        for (int i = 0; i < in.axis_count; ++i) {
            const double v = vel_[i];
            const double dv = decelRate_[i] * T;
            const double nv = std::fabs(v) <= dv ? 0 : v - std::copysign(dv, v);
            pos_[i] += 0.5 * (v + nv) * T;
            vel_[i] = nv;
            still = still && nv == 0;
        }
        if (still) {
            atRest_ = true;
            restAfterReturn_ = false;
            vel_.setZero();
            if (req == SourceRequest::Run) beginRecover(in);
        }
        break;
    }
    case SawPhase::Recovering: {
        const double s = smooth5((in.now_s - recSince_) / std::max(cfg_.recover_s, T));
        pos_ = recFrom_ + (recTo_ - recFrom_) * s;
        if (s >= 1) {
            turnBase_ = recTo_[1];
            phase_ = SawPhase::Waiting;
            atRest_ = true; // look for a sync position ahead
        }
        break;
    }
    case SawPhase::Done:
        pos_[0] = cfg_.wait_position_mm;
        break;
    }

    if (phase_ != SawPhase::Stopping) vel_ = (pos_ - prev) / T;
    out.position = pos_;
    out.velocity = vel_;
    out.torque.setZero();
    out.tool_on = phase_ != SawPhase::Done && !leave && !(atRest_ && req != SourceRequest::Run);
    if (phase_ == SawPhase::Done) {
        out.status = SourceStatus::Done;
    } else if (atRest_ && (phase_ == SawPhase::Waiting || phase_ == SawPhase::Stopping) &&
               req != SourceRequest::Run) {
        out.status = SourceStatus::AtRest;
    }
    // The first cut trims the line's head; piece k is finished by cut k + 1.
    out.point_index = static_cast<std::uint32_t>(std::max(cutsDone_ - 1, 0));
    out.made = out.point_index;
    out.point_count = static_cast<std::uint32_t>(total_);
    out.progress = total_ > 0 ? std::min(1.0, std::max(cutsDone_ - 1, 0) / double(total_)) : 0;
}

} // namespace cutcell
