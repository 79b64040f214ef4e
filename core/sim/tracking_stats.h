#pragma once
// Running tracking-error figures of a cut: per axis max |e| and RMS, and the torch tip's
// position error (FK of actual vs commanded joints) per axis, both in the robot base frame
// and relative to the turning work pipe. Used by the offline simulation and by the engine,
// so both report the same figures. add() is allocation-free.
#include "core/common/types.h"
#include "core/json/json.h"
#include "core/kinematics/tip_model.h"

#include <array>
#include <string>

namespace cutcell {

// Per axis, in the axis's own unit: deg on a rotary axis, mm on a linear one
// (TrackingReport::axis_linear says which; TrackingStats::fill() converts by it).
struct AxisErrorStats {
    double max_abs = 0;
    double rms = 0;
};

// The torch height over a run with a process control on the torch axis (summary.json
// "torch_height"): the standoff error estimated from the arc voltage while the path moved with
// the arc on, THC on or off.
struct TorchHeightFigures {
    bool valid = false;
    bool thc_on = false;
    double cut_height_mm = 0;
    long samples = 0;
    double min_error_mm = 0, max_error_mm = 0, max_abs_error_mm = 0, rms_error_mm = 0;
    // The same while the THC corrected (its Active state): 0 samples with the THC off.
    long active_samples = 0;
    double active_max_abs_error_mm = 0, active_rms_error_mm = 0;
    double max_abs_correction_mm = 0;
    double min_voltage_v = 0, max_voltage_v = 0;
};

struct TrackingReport {
    std::string method;
    bool reachable = true;
    std::string problem;
    double length_mm = 0;
    double cut_time_s = 0;
    double simulated_s = 0;
    long steps = 0;
    double max_direction_deviation_deg = 0;
    // The machine has a tool-tip model (the Cartesian figures mean something); without one the
    // report holds joint figures only.
    bool has_tip = true;
    int axis_count = 0;                       // axes in joints / cruise_joints
    std::array<bool, kMaxAxes> axis_linear{}; // mm instead of rad
    std::array<AxisErrorStats, kMaxAxes> joints{};
    Vec3 cartesian_max_abs_mm = Vec3::Zero(); // tip, base frame
    Vec3 cartesian_min_mm = Vec3::Zero();
    Vec3 cartesian_max_mm = Vec3::Zero();
    Vec3 on_pipe_max_abs_mm = Vec3::Zero(); // tip relative to the work pipe (chuck error included)
    double max_torque_fraction = 0;         // peak |u| / torque limit over all axes
    // The same figures over the constant-speed part of the cut only (ramps excluded).
    std::array<AxisErrorStats, kMaxAxes> cruise_joints{};
    Vec3 cruise_cartesian_max_abs_mm = Vec3::Zero();
    Vec3 cruise_on_pipe_max_abs_mm = Vec3::Zero();
    TorchHeightFigures torch_height;

    // Axis i's figures in its own unit: deg on a rotary axis, mm on a linear one.
    bool linear(int i) const { return axis_linear[static_cast<size_t>(i)]; }
    const char* unit(int i) const { return linear(i) ? "mm" : "deg"; }
    double maxAbs(int i) const { return joints[static_cast<size_t>(i)].max_abs; }
    double rms(int i) const { return joints[static_cast<size_t>(i)].rms; }
};

// The torch tips of one sample (commanded and actual joints), in the base frame and seen
// from the work piece. Computed once per step and shared by every TrackingStats fed that
// sample (overall and cruise figures) and by the engine's telemetry.
struct TipSample {
    bool valid = false; // false: the stats have no tip model (joint figures only)
    Vec3 commanded = Vec3::Zero();
    Vec3 actual = Vec3::Zero();
    Vec3 commanded_on_work = Vec3::Zero();
    Vec3 actual_on_work = Vec3::Zero();
    Vec3 error() const { return actual - commanded; } // FK(actual) - FK(commanded)
};

// The tips of a sample from a machine's tip model (invalid when the model is null).
TipSample tipSample(const TipModel* model, const JointVector& commanded, const JointVector& actual);

class TrackingStats {
  public:
    // The tip comes from the machine's model (the motion engine's programs carry one). A null
    // model gives joint figures only. The model must outlive the stats.
    explicit TrackingStats(const TipModel* model) : model_(model) {}
    void reset();
    // The tips of a sample with this stats' model (allocation-free).
    TipSample tips(const JointVector& commanded, const JointVector& actual) const;
    void add(const JointVector& commanded, const JointVector& actual) {
        add(commanded, actual, tips(commanded, actual));
    }
    // With tips computed once for several stats (they must come from the same model).
    void add(const JointVector& commanded, const JointVector& actual, const TipSample& tips);
    void addTorqueFraction(double f) {
        if (f > maxTorqueFraction_) maxTorqueFraction_ = f;
    }
    // Fills the error fields of a report (or its cruise fields).
    void fill(TrackingReport& r) const;
    void fillCruise(TrackingReport& r) const;
    long samples() const { return n_; }
    // Last Cartesian tip error (base frame), for telemetry.
    const Vec3& lastCartesianError() const { return lastCart_; }

  private:
    const TipModel* model_ = nullptr;
    long n_ = 0;
    JointVector maxAbs_ = JointVector::Zero();
    JointVector sumSq_ = JointVector::Zero();
    Vec3 cartMin_ = Vec3::Zero(), cartMax_ = Vec3::Zero(), workMaxAbs_ = Vec3::Zero();
    Vec3 lastCart_ = Vec3::Zero();
    double maxTorqueFraction_ = 0;
};

// Axes 0 .. axis_count-1, each in its unit (rotary: *_deg, linear: *_mm), named by `names`
// when given (else "axis 0", "axis 1", ...). The Cartesian figures only when has_tip.
json::Value reportToJson(const TrackingReport& r,
                         const std::array<std::string, kMaxAxes>* names = nullptr);

} // namespace cutcell
