#include "core/sim/tracking_stats.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

void TrackingStats::reset() {
    n_ = 0;
    maxAbs_.setZero();
    sumSq_.setZero();
    cartMin_.setZero();
    cartMax_.setZero();
    workMaxAbs_.setZero();
    lastCart_.setZero();
    maxTorqueFraction_ = 0;
}

TipSample tipSample(const TipModel* model, const JointVector& commanded,
                    const JointVector& actual) {
    TipSample s;
    if (!model) return s;
    model->tipPair(commanded, actual, s.commanded, s.actual);
    s.commanded_on_work = model->tipOnWork(commanded, s.commanded);
    s.actual_on_work = model->tipOnWork(actual, s.actual);
    s.valid = true;
    return s;
}

TipSample TrackingStats::tips(const JointVector& commanded, const JointVector& actual) const {
    return tipSample(model_, commanded, actual);
}

void TrackingStats::add(const JointVector& commanded, const JointVector& actual,
                        const TipSample& tips) {
    const JointVector e = commanded - actual;
    maxAbs_ = maxAbs_.cwiseMax(e.cwiseAbs());
    sumSq_ += e.cwiseProduct(e);
    ++n_;
    if (!tips.valid) return;
    lastCart_ = tips.error();
    cartMin_ = cartMin_.cwiseMin(lastCart_);
    cartMax_ = cartMax_.cwiseMax(lastCart_);
    workMaxAbs_ = workMaxAbs_.cwiseMax((tips.actual_on_work - tips.commanded_on_work).cwiseAbs());
}

void TrackingStats::fill(TrackingReport& r) const {
    // The engine's errors are rad on rotary axes and mm on linear ones: set r.axis_linear first.
    for (int i = 0; i < kMaxAxes; ++i) {
        const auto a = static_cast<size_t>(i);
        const auto unit = [&r, a](double v) { return r.axis_linear[a] ? v : rad2deg(v); };
        r.joints[a].max_abs = unit(maxAbs_[i]);
        r.joints[a].rms = unit(n_ ? std::sqrt(sumSq_[i] / static_cast<double>(n_)) : 0);
    }
    r.cartesian_min_mm = cartMin_;
    r.cartesian_max_mm = cartMax_;
    r.cartesian_max_abs_mm = cartMin_.cwiseAbs().cwiseMax(cartMax_.cwiseAbs());
    r.on_pipe_max_abs_mm = workMaxAbs_;
    r.max_torque_fraction = maxTorqueFraction_;
    r.steps = n_;
    r.has_tip = model_ != nullptr;
}

void TrackingStats::fillCruise(TrackingReport& r) const {
    TrackingReport tmp;
    tmp.axis_linear = r.axis_linear;
    fill(tmp);
    r.cruise_joints = tmp.joints;
    r.cruise_cartesian_max_abs_mm = tmp.cartesian_max_abs_mm;
    r.cruise_on_pipe_max_abs_mm = tmp.on_pipe_max_abs_mm;
}

namespace {
json::Value xyz(const Vec3& v) {
    return json::Object{{"x", v.x()}, {"y", v.y()}, {"z", v.z()}};
}
} // namespace

json::Value reportToJson(const TrackingReport& r, const std::array<std::string, kMaxAxes>* names) {
    json::Array joints, cruise;
    const int n = std::clamp(r.axis_count, 0, kMaxAxes);
    for (int i = 0; i < n; ++i) {
        const auto a = static_cast<size_t>(i);
        const bool linear = r.linear(i);
        const std::string maxKey = linear ? "max_abs_error_mm" : "max_abs_error_deg";
        const std::string rmsKey = linear ? "rms_error_mm" : "rms_error_deg";
        const std::string name =
            names && !(*names)[a].empty() ? (*names)[a] : "axis " + std::to_string(i);
        const auto& j = r.joints[a];
        joints.emplace_back(
            json::Object{{"axis", i}, {"name", name}, {maxKey, j.max_abs}, {rmsKey, j.rms}});
        const auto& c = r.cruise_joints[a];
        cruise.emplace_back(json::Object{{"axis", i}, {maxKey, c.max_abs}, {rmsKey, c.rms}});
    }
    json::Object doc{
        {"method", r.method},
        {"reachable", r.reachable},
        {"problem", r.problem},
        {"length_mm", r.length_mm},
        {"cut_time_s", r.cut_time_s},
        {"simulated_s", r.simulated_s},
        {"steps", static_cast<double>(r.steps)},
        {"max_direction_deviation_deg", r.max_direction_deviation_deg},
        {"max_torque_fraction", r.max_torque_fraction},
        {"joints", joints},
    };
    json::Object cruiseDoc{
        {"about", "constant cutting speed only (start and stop ramps excluded)"},
        {"joints", cruise},
    };
    if (r.has_tip) {
        doc.emplace_back(
            "cartesian",
            json::Object{{"frame", "robot base {0}, torch tip, FK(actual) - FK(commanded)"},
                         {"max_abs_error_mm", xyz(r.cartesian_max_abs_mm)},
                         {"min_error_mm", xyz(r.cartesian_min_mm)},
                         {"max_error_mm", xyz(r.cartesian_max_mm)},
                         {"on_pipe_max_abs_error_mm", xyz(r.on_pipe_max_abs_mm)}});
        cruiseDoc.emplace_back("cartesian_max_abs_error_mm", xyz(r.cruise_cartesian_max_abs_mm));
        cruiseDoc.emplace_back("on_pipe_max_abs_error_mm", xyz(r.cruise_on_pipe_max_abs_mm));
    }
    doc.emplace_back("cruise", std::move(cruiseDoc));
    if (const TorchHeightFigures& h = r.torch_height; h.valid)
        doc.emplace_back(
            "torch_height",
            json::Object{{"about", "standoff error = torch height estimated from the arc voltage "
                                   "- cut height, while the path moved with the arc on"},
                         {"thc", h.thc_on ? "on" : "off"},
                         {"cut_height_mm", h.cut_height_mm},
                         {"samples", static_cast<double>(h.samples)},
                         {"min_standoff_error_mm", h.min_error_mm},
                         {"max_standoff_error_mm", h.max_error_mm},
                         {"max_abs_standoff_error_mm", h.max_abs_error_mm},
                         {"rms_standoff_error_mm", h.rms_error_mm},
                         {"while_thc_active",
                          json::Object{{"samples", static_cast<double>(h.active_samples)},
                                       {"max_abs_standoff_error_mm", h.active_max_abs_error_mm},
                                       {"rms_standoff_error_mm", h.active_rms_error_mm}}},
                         {"max_abs_correction_mm", h.max_abs_correction_mm},
                         {"min_arc_voltage_v", h.min_voltage_v},
                         {"max_arc_voltage_v", h.max_voltage_v}});
    return doc;
}

} // namespace cutcell
