#include "core/machines/quick_return/quick_return_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cutcell::quick_return {

namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr const char* kReturnReason = "open-loop torque return stroke";
constexpr const char* kBlendReason = "near a singular point: no crank reference (parabolic blend)";
constexpr const char* kBrakeReason = "braking the crank";
// Where a feed hold rests the crank before a cut: this share of the cutting arc past its top.
constexpr double kTopRestArc = 0.05;
} // namespace

double holdBandwidth(const QuickReturnLawConfig& c, double period_s) {
    return period_s > 0 ? std::min(c.hold_bandwidth, kHoldStepGain / (2 * period_s))
                        : c.hold_bandwidth;
}

namespace {
// The nominal model's inertia seen at the crank, M(q) (kg m^2), and the slider's weight as a
// crank torque (N m).
struct CrankInertia {
    double M = 0, weight = 0;
};
CrankInertia crankInertia(const QuickReturnLawConfig& c, double q) {
    const WhitworthPose p = forwardKinematics(c.dims, q);
    const CrankPlantParams& m = c.model;
    CrankInertia r{m.crank_inertia, 0};
    if (p.closes) {
        const auto rho = extendedJacobian(c.dims, q, p);
        r.M += m.rocker_inertia * rho[2] * rho[2] + m.slider_mass * rho[4] * rho[4];
        r.weight = m.slider_mass * m.gravity * rho[4];
    }
    return r;
}
} // namespace

double holdTorque(const QuickReturnLawConfig& c, double q, double dq, double qRef, double dqRef,
                  double period_s) {
    const CrankInertia m = crankInertia(c, q);
    const double w = holdBandwidth(c, period_s);
    return m.M * (w * w * (qRef - q) + 2 * w * (dqRef - dq)) + m.weight;
}

const char* toString(Experiment e) {
    return e == Experiment::Tracking ? "tracking" : "cutting";
}

const char* toString(QrPhase p) {
    switch (p) {
    case QrPhase::Hold:
        return "holding";
    case QrPhase::Tracking:
        return "tracking";
    case QrPhase::Cut:
        return "cutting stroke";
    case QrPhase::ReturnPush:
        return "open-loop return (push)";
    case QrPhase::ReturnBrake:
        return "open-loop return (brake)";
    case QrPhase::Braking:
        return "braking";
    case QrPhase::Done:
        return "done";
    }
    return "?";
}

QuickReturnLaw::QuickReturnLaw(const QuickReturnLawConfig& c) : c_(c) {
    ctl_.configure(c_.controller, c_.gains);
}

bool QuickReturnLaw::onCutBranch(double q) const {
    double d = std::fmod(q - c_.stroke.q_top, kTwoPi);
    if (d < 0) d += kTwoPi;
    return d > 0 && d < c_.stroke.cut_arc;
}

double QuickReturnLaw::crankForSlider(double y) const {
    // y decreases monotonically along the cutting branch.
    double lo = c_.stroke.q_top, hi = c_.stroke.q_top + c_.stroke.cut_arc;
    for (int i = 0; i < 50; ++i) {
        const double m = 0.5 * (lo + hi);
        const double ym = forwardKinematics(c_.dims, m).y + c_.dims.scale_offset;
        if (ym > y)
            lo = m;
        else
            hi = m;
    }
    return 0.5 * (lo + hi);
}

void QuickReturnLaw::holdAtRest(double q, QrPhase resume) {
    phase_ = QrPhase::Braking;
    brakeAt_ = q;
    rest_ = 0;
    held_ = true;
    holdPending_ = false;
    resumePhase_ = resume;
}

void QuickReturnLaw::start(const SourceInput& in) {
    const DriveFeedback& d = (*in.axes)[static_cast<size_t>(c_.axis)];
    phase_ = c_.experiment == Experiment::Tracking ? QrPhase::Tracking
             : onCutBranch(d.position)             ? QrPhase::Cut
                                                   : QrPhase::ReturnPush;
    t0_ = in.now_s;
    strokes_ = 0;
    rest_ = 0;
    restarted_ = false;
    held_ = false;
    holdPending_ = false;
}

double QuickReturnLaw::nominalAcceleration(double q, double tau) const {
    const CrankInertia m = crankInertia(c_, q);
    return (tau - m.weight) / m.M;
}

QuickReturnLaw::CrankState QuickReturnLaw::predictCrank(double q, double dq, double T,
                                                        int n) const {
    // Over each of the n cycles the torque written n cycles before it acts (tauHist_[0] is the
    // last cycle's), with the load's acceleration of the last fresh cycles.
    CrankState x{q, dq};
    for (int j = 0; j < n; ++j) {
        const double a =
            nominalAcceleration(x.q, tauHist_[static_cast<size_t>(n - 1 - j)]) + loadAcc_;
        x.q += x.dq * T + 0.5 * a * T * T;
        x.dq += a * T;
    }
    return x;
}

double QuickReturnLaw::controlTorque(double q, double y, double dy, double yd, double dyd,
                                     double ddyd, double T, double tSince, double* u) {
    if (!restarted_) {
        ctl_.restart(yd - y, dyd - dy);
        restarted_ = true;
    }
    *u = ctl_.update(yd - y, dyd - dy, ddyd, T, tSince);
    double map;
    if (c_.jacobian_compensator) {
        // Eq. 33: K_rho sign(y'/q'), the sign known per branch (found offline).
        map = onCutBranch(q) ? -c_.k_rho : c_.k_rho;
    } else {
        const WhitworthPose p = forwardKinematics(c_.dims, q);
        map = p.closes ? extendedJacobian(c_.dims, q, p)[4] : 0;
    }
    return map * *u;
}

void QuickReturnLaw::update(const SourceInput& in, SourceOutput& out) {
    const size_t a = static_cast<size_t>(c_.axis);
    const SensorReading& s = (*in.sensors)[static_cast<size_t>(c_.sensor)];
    const DriveFeedback& d = (*in.axes)[a];
    out.position = in.setpoint;
    out.velocity = in.setpoint_velocity;
    out.torque.setZero();
    out.point_count = static_cast<std::uint32_t>(c_.strokes);
    if (!s.valid || !std::isfinite(s.position)) {
        out.status = SourceStatus::Fault;
        out.fault = "slider position sensor: reading not valid";
        return;
    }
    now_ = in.now_s;
    const double q = d.position, dq = d.velocity, T = in.period_s;
    const double y = s.position / 1000; // mm -> m
    const WhitworthPose pose = forwardKinematics(c_.dims, q);
    const double dy = pose.closes ? extendedJacobian(c_.dims, q, pose)[4] * dq : 0;
    // The law's torque reaches the crank n cycles after the feedback was sampled: the drive's
    // actuation delay (over CAN the next SYNC) and the cycles the feedback came late. It is
    // computed for the crank and the reference of then, from the torques already written and
    // not yet acting. Without it the sliding-mode law, a cycle behind its own torque, chattered
    // at the torque limit (over virtualcan at 1 ms: torque fraction 1.0 against 0.72 in process,
    // rms error 2.4 against 1.5 deg). Feedback up to kPredictCycles late is predicted the
    // same way (against the crank plant with the feedback stalled 10 cycles in every 100: max
    // |e| 6.1 deg, 7.4 with no torque while late); older feedback gives no torque (below).
    const double h = in.actuation_delay_s;
    const int base = h > 0 ? std::max(1, static_cast<int>(std::lround(h / T))) : 0;
    const int age = std::max<int>(d.age_cycles, s.age_cycles);
    const int n = base + age;
    const bool history = havePrev_ && in.now_s - nowPrev_ < 1.5 * T;
    const bool predict = n > 0 && n <= kPredictCycles && history && pose.closes;
    double qAhead = q, yAhead = y, dyAhead = dy;
    if (predict) {
        const CrankState ahead = predictCrank(q, dq, T, n);
        const WhitworthPose p = forwardKinematics(c_.dims, ahead.q);
        if (p.closes) {
            qAhead = ahead.q;
            yAhead = y + (p.y - pose.y);
            dyAhead = extendedJacobian(c_.dims, ahead.q, p)[4] * ahead.dq;
        }
    }
    const double lead = predict ? n * T : 0.0;
    double tau = 0, u = 0, yd = y, dyd = 0, qRef = q, dqRef = dq;
    bool supervised = false;
    const char* reason = kBrakeReason;

    if (in.request == SourceRequest::Track) {
        phase_ = QrPhase::Hold;
        qRef = in.setpoint[static_cast<Eigen::Index>(a)];
        dqRef = in.setpoint_velocity[static_cast<Eigen::Index>(a)];
        tau = holdTorque(c_, q, dq, qRef, dqRef, T);
        supervised = true;
    } else {
        const bool run = in.request == SourceRequest::Run;
        const bool hold = in.request == SourceRequest::FeedHold;
        // Resume after a feed hold: on from where the hold rested.
        if (run && held_ && phase_ == QrPhase::Braking) {
            held_ = false;
            phase_ = resumePhase_;
            if (phase_ == QrPhase::Cut) {
                t0_ = now_;
                restarted_ = false;
            } else if (phase_ == QrPhase::Tracking) {
                t0_ = now_ - heldAt_;
            }
        }
        if (!hold) holdPending_ = false; // resumed while finishing the stroke, or a stop
        const bool stroke = phase_ == QrPhase::Cut || phase_ == QrPhase::ReturnPush ||
                            phase_ == QrPhase::ReturnBrake;
        if (hold && stroke) {
            // A feed hold rests the crank where a stroke may begin again: the cut is finished
            // (a cutter never stops in the workpiece) and the crank rests past its end; the
            // open-loop return is finished (braked half-way, its torques cannot start it again)
            // and the crank rests at the top, where the next cut begins.
            holdPending_ = true;
        } else if (!run && phase_ != QrPhase::Braking && phase_ != QrPhase::Done) {
            // Abort or a controlled stop (and a hold while tracking): to rest where it is.
            if (hold) {
                held_ = true;
                resumePhase_ = phase_;
                heldAt_ = now_ - t0_;
            }
            phase_ = QrPhase::Braking;
            rest_ = 0;
            brakeAt_ = q;
        }
        const double tSince = now_ - t0_;
        switch (phase_) {
        case QrPhase::Hold:
        case QrPhase::Tracking: {
            phase_ = QrPhase::Tracking;
            const double w = c_.track_omega, A = c_.track_amplitude;
            yd = c_.track_offset + A * std::sin(w * tSince);
            dyd = A * w * std::cos(w * tSince);
            const double ta = tSince + lead;
            tau = controlTorque(qAhead, yAhead, dyAhead, c_.track_offset + A * std::sin(w * ta),
                                A * w * std::cos(w * ta), -A * w * w * std::sin(w * ta), T, ta, &u);
            qRef = q + wrapAngle(crankForSlider(yd) - q);
            dqRef = dq;
            supervised = true;
            if (tSince >= c_.track_duration) {
                phase_ = QrPhase::Braking;
                brakeAt_ = q;
                rest_ = 0;
            }
            break;
        }
        case QrPhase::Cut: {
            const ProfileSample r = sampleProfile(c_.profile, tSince);
            yd = r.y;
            dyd = r.dy;
            const ProfileSample ra = lead > 0 ? sampleProfile(c_.profile, tSince + lead) : r;
            tau = controlTorque(qAhead, yAhead, dyAhead, ra.y, ra.dy, ra.ddy, T, tSince + lead, &u);
            const double lo = std::min(c_.profile.y_a, c_.profile.y_b);
            const double hi = std::max(c_.profile.y_a, c_.profile.y_b);
            if (r.y >= lo && r.y <= hi) {
                supervised = true;
                qRef = q + wrapAngle(crankForSlider(r.y) - q);
            } else {
                reason = kBlendReason;
            }
            if (!onCutBranch(q) && dq < 0) {
                out.status = SourceStatus::Fault;
                out.fault = "cutting stroke: the crank was driven back through the top singular "
                            "point (the controller cannot hold the slider against the contact "
                            "force)";
                return;
            }
            if (tSince > c_.profile.duration() + c_.cut_timeout) {
                out.status = SourceStatus::Fault;
                out.fault = "cutting stroke stalled: the slider did not reach the end of the "
                            "stroke in time (the controller cannot push through the contact "
                            "force)";
                return;
            }
            const bool past = !onCutBranch(q);
            const bool arrived =
                tSince >= c_.profile.duration() && std::fabs(y - c_.stroke.y_bottom) < 0.002;
            if (past || arrived) {
                ++strokes_;
                if (strokes_ >= c_.strokes) {
                    phase_ = QrPhase::Braking;
                    brakeAt_ = q;
                    rest_ = 0;
                } else if (holdPending_) {
                    holdAtRest(q, QrPhase::ReturnPush);
                } else {
                    phase_ = QrPhase::ReturnPush;
                }
            }
            break;
        }
        case QrPhase::ReturnPush:
            reason = kReturnReason;
            tau = c_.return_torque_1;
            // Switched on the crank of when the switch takes effect (ahead of late feedback).
            if (yAhead >= 0.5 * (c_.stroke.y_top + c_.stroke.y_bottom))
                phase_ = QrPhase::ReturnBrake;
            break;
        case QrPhase::ReturnBrake:
            reason = kReturnReason;
            tau = c_.return_torque_2;
            if (dq <= 0) {
                out.status = SourceStatus::Fault;
                out.fault = "open-loop return stalled before the top of the stroke: raise "
                            "return_torque_1 or lower |return_torque_2|";
                return;
            }
            if (onCutBranch(qAhead)) {
                if (holdPending_) {
                    // At rest a little into the cutting branch: held right at its top, the
                    // hold's small hunting crossed back over the singular point and the resumed
                    // run took that for the end of a stroke (then stalled in its return).
                    double into = std::fmod(qAhead - c_.stroke.q_top, kTwoPi);
                    if (into < 0) into += kTwoPi;
                    holdAtRest(qAhead + std::max(0.0, kTopRestArc * c_.stroke.cut_arc - into),
                               QrPhase::Cut);
                } else {
                    phase_ = QrPhase::Cut;
                    t0_ = now_;
                    restarted_ = false;
                }
            }
            break;
        case QrPhase::Braking:
        case QrPhase::Done: {
            // Still fast (an abort in the open-loop return, ~1 rev/s): damp the speed only and
            // hold where the crank comes to rest; pulling it back to where the stop began made
            // the torque-limited crank overshoot and swing for ever (never at rest).
            if (std::fabs(dq) > 10 * c_.rest_speed) brakeAt_ = q;
            tau = holdTorque(c_, q, dq, brakeAt_, 0, T);
            rest_ = std::fabs(dq) < c_.rest_speed ? rest_ + 1 : 0;
            if (rest_ >= c_.rest_cycles) {
                if (run) phase_ = QrPhase::Done;
                out.status = run ? SourceStatus::Done : SourceStatus::AtRest;
            }
            break;
        }
        }
    }
    tau = std::clamp(tau, -c_.torque_limit, c_.torque_limit);
    // Feedback older than the prediction reaches says where the crank was, not where it is:
    // no torque from it (the open-loop return's does not depend on the feedback: it stays).
    const bool openLoop = phase_ == QrPhase::ReturnPush || phase_ == QrPhase::ReturnBrake;
    if (!openLoop && age > 0 && !predict) tau = 0;
    // The load's acceleration over the last cycle, from two fresh samples in a row: what the
    // crank did less what the torque acting then (written `base` cycles before) explains.
    if (base > 0 && base <= kPredictCycles && history && age == 0 && prevAge_ == 0) {
        const double load =
            (dq - dqPrev_) / T - nominalAcceleration(qPrev_, tauHist_[static_cast<size_t>(base)]);
        loadAcc_ += T / (T + kLoadFilterS) * (load - loadAcc_);
    } else if (!history) {
        loadAcc_ = 0;
    }
    for (size_t j = kPredictCycles; j > 0; --j)
        tauHist_[j] = tauHist_[j - 1];
    tauHist_[0] = tau;
    qPrev_ = q;
    dqPrev_ = dq;
    nowPrev_ = in.now_s;
    prevAge_ = age;
    havePrev_ = true;
    const Eigen::Index ai = static_cast<Eigen::Index>(a);
    out.position[ai] = supervised ? qRef : q;
    out.velocity[ai] = supervised ? dqRef : dq;
    out.torque[ai] = tau;
    out.supervised[a] = supervised;
    if (!supervised) out.unsupervised_reason = reason;
    out.point_index = static_cast<std::uint32_t>(strokes_);
    out.made = out.point_index;
    out.progress = c_.experiment == Experiment::Tracking
                       ? std::min(1.0, (now_ - t0_) / c_.track_duration)
                       : static_cast<double>(strokes_) / std::max(1, c_.strokes);
    last_ = {now_ - t0_, y, dy, yd, dyd, u, tau, phase_};
}

} // namespace cutcell::quick_return
