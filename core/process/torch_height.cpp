#include "core/process/torch_height.h"

#include "core/common/c_format.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

namespace cutcell {

namespace {

// One field of a spec and its range [lo, hi] (lo excluded when loOpen).
struct Field {
    const char* name;
    double value;
    const char* unit;
    double lo, hi;
    bool loOpen;
};

Outcome checkFields(std::initializer_list<Field> fields) {
    for (const Field& f : fields) {
        const bool ok = std::isfinite(f.value) && (f.loOpen ? f.value > f.lo : f.value >= f.lo) &&
                        f.value <= f.hi;
        if (!ok)
            return Outcome::refuse(messageC(f.loOpen ? "%s = %.6g %s is outside (%.6g, %.6g] %s"
                                                     : "%s = %.6g %s is outside [%.6g, %.6g] %s",
                                            f.name, f.value, f.unit, f.lo, f.hi, f.unit));
    }
    return Outcome::done();
}

// The chart reader's ranges (core/process/cut_chart.cpp) for the figures shared with it.
constexpr double kVoltsPerMmLo = 0.1, kVoltsPerMmHi = 50;
constexpr double kArcVoltageLo = 30, kArcVoltageHi = 400;

} // namespace

ThcProcess thcProcessFor(const CutChart& chart, const CutRow& row) {
    return thcProcessFor(row, chart.volts_per_mm);
}

ThcProcess thcProcessFor(const CutRow& row, std::optional<double> voltsPerMm) {
    ThcProcess p;
    if (const auto h = row.get(CutFigure::CutHeightMm)) {
        p.cut_height_mm = *h;
        p.cut_height_from_chart = true;
    }
    if (const auto v = row.get(CutFigure::ArcVoltageV)) {
        p.arc_voltage_v = *v;
        p.arc_voltage_from_chart = true;
    }
    // 0 or absent: the chart has no slope for this consumable set.
    if (voltsPerMm && *voltsPerMm > 0) {
        p.volts_per_mm = *voltsPerMm;
        p.volts_per_mm_from_chart = true;
    }
    p.cut_speed_mm_s = row.cutSpeedMmMin() / 60;
    p.pierce_delay_s = row.get(CutFigure::PierceDelayS).value_or(0);
    return p;
}

Outcome checkArcModelSpec(const ArcModelSpec& s) {
    return checkFields({
        {"arc_voltage_v", s.arc_voltage_v, "V", kArcVoltageLo, kArcVoltageHi, false},
        {"cut_height_mm", s.cut_height_mm, "mm", 0, 50, false},
        {"volts_per_mm", s.volts_per_mm, "V/mm", kVoltsPerMmLo, kVoltsPerMmHi, false},
        {"noise_v", s.noise_v, "V", 0, 50, false},
    });
}

double ArcModel::voltage(double standoff_mm) {
    double v = s_.arc_voltage_v + s_.volts_per_mm * (standoff_mm - s_.cut_height_mm);
    if (s_.noise_v > 0) v += std::uniform_real_distribution<double>(-s_.noise_v, s_.noise_v)(rng_);
    return v;
}

Outcome checkTorchAxisSpec(const TorchAxisSpec& s) {
    return checkFields({
        {"lag_s", s.lag_s, "s", 0, 1, false},
        {"max_velocity_mm_s", s.max_velocity_mm_s, "mm/s", 0, 1000, true},
        {"max_acceleration_mm_s2", s.max_acceleration_mm_s2, "mm/s^2", 0, 100000, true},
        {"stroke_mm", s.stroke_mm, "mm", 0, 100, true},
    });
}

double TorchAxis::step(double command_mm, double dt) {
    // First-order lag toward the command (a position loop of bandwidth 1 / lag), within the
    // velocity and acceleration limits; lag 0: reach the command in one cycle if the limits let.
    const double cmd = std::clamp(command_mm, -s_.stroke_mm, s_.stroke_mm);
    const double want = (cmd - pos_) / std::max(s_.lag_s, dt);
    const double dv = s_.max_acceleration_mm_s2 * dt;
    vel_ = std::clamp(std::clamp(want, vel_ - dv, vel_ + dv), -s_.max_velocity_mm_s,
                      s_.max_velocity_mm_s);
    pos_ += vel_ * dt;
    if (std::fabs(pos_) >= s_.stroke_mm) { // on the end stop
        pos_ = std::clamp(pos_, -s_.stroke_mm, s_.stroke_mm);
        vel_ = 0;
    }
    return pos_;
}

Outcome checkThcSpec(const ThcSpec& s) {
    return checkFields({
        {"setpoint_v", s.setpoint_v, "V", kArcVoltageLo, kArcVoltageHi, false},
        {"volts_per_mm", s.volts_per_mm, "V/mm", kVoltsPerMmLo, kVoltsPerMmHi, false},
        {"delay_s", s.delay_s, "s", 0, 10, false},
        {"kp_per_s", s.kp_per_s, "1/s", 0, 1000, true},
        {"ki_per_s2", s.ki_per_s2, "1/s^2", 0, 100000, false},
        {"deadband_v", s.deadband_v, "V", 0, 20, false},
        {"max_velocity_mm_s", s.max_velocity_mm_s, "mm/s", 0, 1000, true},
        {"max_acceleration_mm_s2", s.max_acceleration_mm_s2, "mm/s^2", 0, 100000, true},
        {"max_correction_mm", s.max_correction_mm, "mm", 0, 20, true},
        {"anti_dive_fraction", s.anti_dive_fraction, "x the cut speed", 0, 1, false},
        {"lowpass_hz", s.lowpass_hz, "Hz", 0, 1000, false},
    });
}

const char* toString(ThcState s) {
    switch (s) {
    case ThcState::Disabled:
        return "off";
    case ThcState::ArcOff:
        return "no arc";
    case ThcState::Pierce:
        return "pierce";
    case ThcState::Settling:
        return "arc settling";
    case ThcState::Active:
        return "active";
    case ThcState::AntiDive:
        return "anti-dive hold";
    }
    return "?";
}

ThcController::ThcController(const ThcSpec& s) : s_(s) {
    const Outcome o = checkThcSpec(s);
    if (!o.ok()) throw std::invalid_argument(o.message);
    reset();
}

void ThcController::reset() {
    out_ = ThcOutput{};
    out_.state = s_.enabled ? ThcState::ArcOff : ThcState::Disabled;
    settle_s_ = 0;
    integral_ = 0;
    haveVoltage_ = false;
}

const ThcOutput& ThcController::update(const ThcInput& in) {
    const double T = in.period_s;
    // The measured voltage, filtered, and the height error it means (only with an arc: without
    // one the voltage is the open-circuit or zero, not a height).
    if (in.arc_ok) {
        if (!haveVoltage_ || s_.lowpass_hz <= 0) {
            out_.voltage_v = in.arc_voltage_v;
        } else {
            const double alpha = 1 - std::exp(-2 * kPi * s_.lowpass_hz * T);
            out_.voltage_v += alpha * (in.arc_voltage_v - out_.voltage_v);
        }
        haveVoltage_ = true;
        out_.height_error_mm = (out_.voltage_v - s_.setpoint_v) / s_.volts_per_mm;
    } else {
        haveVoltage_ = false;
        out_.height_error_mm = 0;
    }

    // The state. Every state but Active holds: the velocity goes to 0 at once (a hold is a
    // protective action; the drive's own acceleration limit decelerates the axis).
    if (!s_.enabled) {
        out_.state = ThcState::Disabled;
    } else if (!in.arc_ok) {
        out_.state = ThcState::ArcOff;
        settle_s_ = 0; // a new arc settles again
        integral_ = 0;
    } else if (!in.moving) {
        out_.state = ThcState::Pierce;
        settle_s_ = 0;
    } else {
        settle_s_ += T;
        const bool fastEnough = in.cut_speed_mm_s > 0 &&
                                in.path_speed_mm_s >= s_.anti_dive_fraction * in.cut_speed_mm_s;
        if (settle_s_ < s_.delay_s - 0.5 * T)
            out_.state = ThcState::Settling;
        else
            out_.state = fastEnough ? ThcState::Active : ThcState::AntiDive;
    }
    if (out_.state != ThcState::Active) {
        out_.velocity_mm_s = 0;
        return out_;
    }

    // P (PI when ki > 0) on the height error beyond the deadband (continuous at its edge: no
    // jump to the full error when leaving it); inside the deadband nothing moves and nothing
    // integrates. The correction integrates the velocity, so P alone already tracks a surface
    // moving at rate r with a lag of r / kp (type 1).
    const double dbMm = s_.deadband_v / s_.volts_per_mm;
    const double e = out_.height_error_mm;
    double want = 0;
    if (std::fabs(e) > dbMm) {
        const double ed = e - std::copysign(dbMm, e);
        // Conditional integration (anti-windup): not while pushing against a limit.
        const double trial = s_.kp_per_s * ed + s_.ki_per_s2 * (integral_ + ed * T);
        const bool atLimit = std::fabs(trial) > s_.max_velocity_mm_s ||
                             (ed > 0 && out_.correction_mm >= s_.max_correction_mm) ||
                             (ed < 0 && out_.correction_mm <= -s_.max_correction_mm);
        if (!atLimit) integral_ += ed * T;
        want = s_.kp_per_s * ed + s_.ki_per_s2 * integral_;
    }
    // Toward a travel limit no faster than the axis can stop in the room left (braking at
    // max_acceleration, in whole cycles: v^2 / 2a + v T / 2 <= room), so the travel limit is
    // reached without a velocity step.
    const double a = s_.max_acceleration_mm_s2, dv = a * T;
    const auto stopSpeed = [&](double room) {
        return -0.5 * dv + std::sqrt(0.25 * dv * dv + 2 * a * std::max(room, 0.0));
    };
    want = std::clamp(want, -stopSpeed(s_.max_correction_mm + out_.correction_mm),
                      stopSpeed(s_.max_correction_mm - out_.correction_mm));
    double v = std::clamp(want, out_.velocity_mm_s - dv, out_.velocity_mm_s + dv);
    v = std::clamp(v, -s_.max_velocity_mm_s, s_.max_velocity_mm_s);
    double c = out_.correction_mm + v * T;
    if (std::fabs(c) > s_.max_correction_mm) { // rounding only
        c = std::clamp(c, -s_.max_correction_mm, s_.max_correction_mm);
        v = (c - out_.correction_mm) / T;
    }
    out_.correction_mm = c;
    out_.velocity_mm_s = v;
    return out_;
}

void StandoffStats::add(double e) {
    if (count == 0) {
        min_mm = max_mm = e;
    } else {
        min_mm = std::min(min_mm, e);
        max_mm = std::max(max_mm, e);
    }
    max_abs_mm = std::max(max_abs_mm, std::fabs(e));
    sum_sq += e * e;
    ++count;
}

double StandoffStats::rms() const {
    return count > 0 ? std::sqrt(sum_sq / static_cast<double>(count)) : 0;
}

} // namespace cutcell
