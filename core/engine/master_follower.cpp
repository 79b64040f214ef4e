#include "core/engine/master_follower.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

const char* toString(SyncState s) {
    switch (s) {
    case SyncState::Waiting:
        return "waiting";
    case SyncState::Synchronizing:
        return "synchronizing";
    case SyncState::InSync:
        return "in sync";
    case SyncState::Returning:
        return "returning";
    case SyncState::Stopping:
        return "stopping";
    case SyncState::Done:
        return "done";
    }
    return "?";
}

namespace {
double smoothstep5(double u) {
    u = std::clamp(u, 0.0, 1.0);
    return u * u * u * (10 - 15 * u + 6 * u * u);
}
} // namespace

MasterFollower::MasterFollower(const MasterFollowerConfig& config)
    : cfg_(config), filter_(config.filter_alpha, config.filter_beta) {
    cutLength_.store(config.cut_length);
}

double MasterFollower::coupled(int axis, double m) const {
    const AxisCoupling& c = cfg_.couplings[static_cast<size_t>(axis)];
    if (c.kind == CouplingKind::Gear) return c.slave_sync + c.ratio * (m - sync_);
    if (c.kind == CouplingKind::Cam)
        return cams_.front()[static_cast<size_t>(c.cam)].at(m - sync_) + c.cam_offset;
    return cfg_.wait_position[axis];
}

void MasterFollower::start(const SourceInput& in) {
    const SensorReading& r = (*in.sensors)[static_cast<size_t>(cfg_.master_sensor)];
    filter_.reset(r.position, r.valid ? r.velocity : 0);
    state_ = SyncState::Waiting;
    sync_ = cfg_.first_sync;
    camCycle_ = 0;
    cutsDone_ = 0;
    restAfterReturn_ = false;
    atRest_ = true; // the first Run checks that the sync-in is still ahead
    pos_ = in.setpoint;
    vel_.setZero();
}

void MasterFollower::beginReturn(const SourceInput& in) {
    const double T = std::max(cfg_.return_s, in.period_s);
    retX0_ = pos_;
    retV0_ = vel_;
    // Rest-to-rest quintic with an initial velocity (zero acceleration at both ends).
    const JointVector D = cfg_.wait_position - pos_ - vel_ * T;
    const JointVector E = -vel_ * T;
    retA_ = 10 * D - 4 * E;
    retB_ = 7 * E - 15 * D;
    retC_ = 6 * D - 3 * E;
    retSince_ = in.now_s;
    state_ = SyncState::Returning;
}

void MasterFollower::update(const SourceInput& in, SourceOutput& out) {
    const double T = in.period_s;
    const SensorReading& r = (*in.sensors)[static_cast<size_t>(cfg_.master_sensor)];
    out.point_count = static_cast<std::uint32_t>(cfg_.cut_count);
    out.point_index = static_cast<std::uint32_t>(cutsDone_);
    out.progress = cfg_.cut_count > 0 ? static_cast<double>(cutsDone_) / cfg_.cut_count : 0;
    if (!r.valid || !std::isfinite(r.position)) {
        out.position = pos_;
        out.velocity.setZero();
        out.status = SourceStatus::Fault;
        out.fault = "master encoder: reading not valid";
        return;
    }
    const double m = filter_.update(r.position, T, r.age_cycles);
    out.master_position = m;
    const JointVector prev = pos_;
    const SourceRequest req = in.request;
    const bool leave = req == SourceRequest::Abort || req == SourceRequest::ControlledStop;
    const int n = in.axis_count;

    // A new cam table: at once while not coupled, else at the cam-cycle boundary.
    const double period = cams_.front()[0].period;
    const long cycleNow = period > 0 ? static_cast<long>(std::floor((m - sync_) / period)) : 0;
    if (state_ == SyncState::Waiting || state_ == SyncState::Done) {
        if (cams_.takePublished()) ++camSwaps_;
    } else if (cycleNow != camCycle_ && cams_.pending()) {
        if (cams_.takePublished()) ++camSwaps_;
    }
    camCycle_ = cycleNow;

    if (leave && (state_ == SyncState::Synchronizing || state_ == SyncState::InSync ||
                  state_ == SyncState::Returning)) {
        // Decelerate every axis from its velocity to rest in decel_s.
        state_ = SyncState::Stopping;
        decelRate_ = vel_.cwiseAbs() / std::max(cfg_.decel_s, T);
    }
    if (req == SourceRequest::FeedHold &&
        (state_ == SyncState::Synchronizing || state_ == SyncState::InSync ||
         state_ == SyncState::Returning)) {
        restAfterReturn_ = true;
        // Coupled with no end of the cut (sync_span 0): there is no cut to finish, leave now.
        if (cfg_.sync_span <= 0 && state_ != SyncState::Returning) {
            state_ = SyncState::Stopping;
            decelRate_ = vel_.cwiseAbs() / std::max(cfg_.decel_s, T);
        }
    }

    switch (state_) {
    case SyncState::Waiting: {
        pos_ = cfg_.wait_position;
        if (req != SourceRequest::Run) {
            atRest_ = true;
            break;
        }
        if (atRest_) {
            // Started or resumed: wait for the next sync position whose sync-in is still ahead
            // of the master (a sync-in begun in its middle would jump).
            atRest_ = false;
            const double L = cutLength_.load(std::memory_order_relaxed);
            while (L > 0 && m > sync_ - cfg_.start_distance)
                sync_ += L;
            if (m > sync_ - cfg_.start_distance) {
                out.status = SourceStatus::Fault;
                out.fault = "the master is already past the start of the sync-in";
                return;
            }
        }
        if (m >= sync_ - cfg_.start_distance) {
            if (m > sync_) {
                out.status = SourceStatus::Fault;
                out.fault = "master passed the sync position before synchronizing";
                return;
            }
            state_ = SyncState::Synchronizing;
        } else {
            break;
        }
        [[fallthrough]];
    }
    case SyncState::Synchronizing: {
        const double D = std::max(cfg_.start_distance, 1e-12);
        const double s = smoothstep5((m - (sync_ - D)) / D);
        for (int i = 0; i < n; ++i) {
            const double w = cfg_.wait_position[i];
            pos_[i] = w + (coupled(i, m) - w) * s;
        }
        if (m >= sync_) state_ = SyncState::InSync;
        break;
    }
    case SyncState::InSync:
        for (int i = 0; i < n; ++i)
            pos_[i] = coupled(i, m);
        if (cfg_.sync_span > 0 && m >= sync_ + cfg_.sync_span) beginReturn(in);
        break;
    case SyncState::Returning: {
        const double Tr = std::max(cfg_.return_s, T);
        const double u = std::min((in.now_s - retSince_) / Tr, 1.0);
        const double u2 = u * u, u3 = u2 * u;
        pos_ = retX0_ + retV0_ * (Tr * u) + retA_ * u3 + retB_ * (u3 * u) + retC_ * (u3 * u2);
        if (u >= 1) {
            pos_ = cfg_.wait_position;
            ++cutsDone_;
            if (cfg_.cut_count > 0 && cutsDone_ >= cfg_.cut_count) {
                state_ = SyncState::Done;
            } else {
                sync_ += cutLength_.load(std::memory_order_relaxed);
                state_ = SyncState::Waiting;
                atRest_ = restAfterReturn_;
                restAfterReturn_ = false;
            }
        }
        break;
    }
    case SyncState::Stopping: {
        bool moving = false;
        for (int i = 0; i < n; ++i) {
            const double v = vel_[i];
            const double dv = decelRate_[i] * T;
            const double nv = std::fabs(v) <= dv ? 0 : v - std::copysign(dv, v);
            pos_[i] += 0.5 * (v + nv) * T;
            vel_[i] = nv;
            moving = moving || nv != 0;
        }
        if (!moving) {
            // At rest off the line: the next Run (resume) returns to the wait positions first.
            atRest_ = true;
            restAfterReturn_ = false;
            vel_.setZero();
            if (req == SourceRequest::Run) beginReturn(in);
        }
        break;
    }
    case SyncState::Done:
        pos_ = cfg_.wait_position;
        break;
    }

    if (state_ != SyncState::Stopping) vel_ = (pos_ - prev) / T;
    out.position = pos_;
    out.velocity = vel_;
    out.torque.setZero();
    const bool coupledNow = state_ == SyncState::Synchronizing || state_ == SyncState::InSync;
    out.tool_on = cfg_.tool_in_sync_only ? coupledNow : state_ != SyncState::Done;
    // Leaving the line, or resting on a hold: the tool goes off.
    if (leave || (atRest_ && req != SourceRequest::Run)) out.tool_on = false;
    if (state_ == SyncState::Done) {
        out.status = SourceStatus::Done;
        out.tool_on = false;
    } else if (atRest_ && (state_ == SyncState::Waiting || state_ == SyncState::Stopping) &&
               req != SourceRequest::Run) {
        out.status = SourceStatus::AtRest;
    }
    out.point_index = static_cast<std::uint32_t>(cutsDone_);
    out.progress = cfg_.cut_count > 0 ? static_cast<double>(cutsDone_) / cfg_.cut_count : 0;
}

} // namespace cutcell
