#include "core/engine/pd_slider_law.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

const char* toString(SliderPhase p) {
    switch (p) {
    case SliderPhase::Track:
        return "tracking";
    case SliderPhase::Stroke:
        return "cutting stroke";
    case SliderPhase::Return:
        return "open-loop return";
    case SliderPhase::Catch:
        return "catching";
    case SliderPhase::Braking:
        return "braking";
    case SliderPhase::Done:
        return "done";
    }
    return "?";
}

double PdSliderLaw::pd(double xRef, double vRef, double x, double v) const {
    return std::clamp(cfg_.kp * (xRef - x) + cfg_.kd * (vRef - v), -cfg_.force_limit,
                      cfg_.force_limit);
}

void PdSliderLaw::start(const SourceInput& in) {
    (void)in;
    phase_ = SliderPhase::Stroke;
    ref_ = cfg_.stroke_from;
    strokes_ = 0;
    restCount_ = 0;
    caught_ = false;
}

void PdSliderLaw::update(const SourceInput& in, SourceOutput& out) {
    const int a = cfg_.axis;
    const SensorReading& s = (*in.sensors)[static_cast<size_t>(cfg_.sensor)];
    const DriveFeedback& d = (*in.axes)[static_cast<size_t>(a)];
    out.position = in.setpoint;
    out.velocity = in.setpoint_velocity;
    out.torque.setZero();
    out.point_count = static_cast<std::uint32_t>(cfg_.stroke_count);
    out.point_index = static_cast<std::uint32_t>(strokes_);
    out.progress = cfg_.stroke_count > 0 ? static_cast<double>(strokes_) / cfg_.stroke_count : 0;
    if (!s.valid || !std::isfinite(s.position)) {
        out.status = SourceStatus::Fault;
        out.fault = "slider position sensor: reading not valid";
        return;
    }
    const double x = s.position, v = d.velocity, T = in.period_s;
    double xRef = x, vRef = 0, force = 0;
    bool supervised = true;

    if (in.request == SourceRequest::Track) {
        phase_ = SliderPhase::Track;
        xRef = in.setpoint[a];
        vRef = in.setpoint_velocity[a];
        force = pd(xRef, vRef, x, v);
    } else {
        const bool run = in.request == SourceRequest::Run;
        if (!run && (phase_ == SliderPhase::Stroke || phase_ == SliderPhase::Track)) {
            phase_ = SliderPhase::Braking;
            brakeAt_ = x;
            restCount_ = 0;
        }
        if (run && phase_ == SliderPhase::Braking) { // resume: the stroke goes on from here
            phase_ = SliderPhase::Stroke;
            ref_ = std::clamp(brakeAt_, cfg_.stroke_from, cfg_.stroke_to);
        }
        switch (phase_) {
        case SliderPhase::Track:
        case SliderPhase::Stroke:
            phase_ = SliderPhase::Stroke;
            vRef = cfg_.stroke_speed * in.override_fraction;
            ref_ += vRef * T;
            if (ref_ >= cfg_.stroke_to) {
                ref_ = cfg_.stroke_to;
                vRef = 0;
            }
            xRef = ref_;
            force = pd(xRef, vRef, x, v);
            if (ref_ >= cfg_.stroke_to && x >= cfg_.stroke_to - cfg_.catch_window) {
                ++strokes_;
                phase_ = SliderPhase::Return;
            }
            break;
        case SliderPhase::Return:
            supervised = false;
            force = cfg_.return_force;
            if (x <= cfg_.stroke_from + cfg_.catch_distance) {
                phase_ = SliderPhase::Catch;
                caught_ = false;
                restCount_ = 0;
            }
            break;
        case SliderPhase::Catch:
            xRef = cfg_.stroke_from;
            force = pd(xRef, 0, x, v);
            caught_ = caught_ || std::fabs(x - xRef) < cfg_.catch_window;
            supervised = caught_;
            restCount_ = caught_ && std::fabs(v) < cfg_.rest_speed ? restCount_ + 1 : 0;
            if (restCount_ >= cfg_.rest_cycles) {
                if (strokes_ >= cfg_.stroke_count) {
                    phase_ = SliderPhase::Done;
                } else if (run) {
                    phase_ = SliderPhase::Stroke;
                    ref_ = cfg_.stroke_from;
                }
            }
            break;
        case SliderPhase::Braking:
            xRef = brakeAt_;
            force = pd(xRef, 0, x, v);
            restCount_ = std::fabs(v) < cfg_.rest_speed ? restCount_ + 1 : 0;
            break;
        case SliderPhase::Done:
            xRef = cfg_.stroke_from;
            force = pd(xRef, 0, x, v);
            break;
        }
        if (phase_ == SliderPhase::Done)
            out.status = SourceStatus::Done;
        else if (!run &&
                 (phase_ == SliderPhase::Braking ||
                  (phase_ == SliderPhase::Catch && restCount_ >= cfg_.rest_cycles)) &&
                 restCount_ >= cfg_.rest_cycles)
            out.status = SourceStatus::AtRest;
    }
    out.position[a] = supervised ? xRef : x;
    out.velocity[a] = supervised ? vRef : v;
    out.torque[a] = force;
    out.supervised[static_cast<size_t>(a)] = supervised;
    if (!supervised)
        out.unsupervised_reason = phase_ == SliderPhase::Return
                                      ? "open-loop torque return stroke"
                                      : "catching the slider after the open-loop return";
    out.point_index = static_cast<std::uint32_t>(strokes_);
    out.progress = cfg_.stroke_count > 0 ? static_cast<double>(strokes_) / cfg_.stroke_count : 0;
}

} // namespace cutcell
