#include "core/machines/pipe_robot/robot_torch_height.h"

#include "core/common/c_format.h"
#include "core/geometry/cut_path.h"
#include "core/machine/pipe_joint_section.h"
#include "core/process/process_spec.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

RobotTorchHeightSetup robotTorchHeightSetup(const Job& job) {
    RobotTorchHeightSetup s;
    const TorchHeightSpec& t = job.process.torch_height;
    if (!job.process.used || !t.used) return s;
    s.used = true;
    const ProcessSettings settings = resolveProcess(job.process, cutPartWallMm(job));
    if (!settings.ok()) {
        s.problem = settings.outcome.message;
        s.problem_key = settings.outcome.key;
        return s;
    }
    s.process = thcProcessFor(settings.effective, settings.volts_per_mm);
    s.cut_speed_mm_s = job.cut.speed_mm_s;
    s.thc.enabled = t.thc;
    s.thc.setpoint_v = s.process.arc_voltage_v; // the chart's voltage at the cut height
    s.thc.volts_per_mm = s.process.volts_per_mm;
    s.thc.kp_per_s = kRobotThcKpPerS;
    s.arc = {.arc_voltage_v = s.process.arc_voltage_v,
             .cut_height_mm = s.process.cut_height_mm,
             .volts_per_mm = s.process.volts_per_mm,
             .noise_v = t.arc_noise_v};
    s.pipe = {.radius_mm = CutGeometry(job).workRadius(),
              .ovality_mm = t.ovality_mm,
              .major_axis_deg = t.major_axis_deg,
              .runout_mm = t.runout_mm,
              .runout_deg = t.runout_deg,
              .taper_mm_per_m = t.taper_mm_per_m};
    // The checkers' messages start with the field's name: the job key is that under
    // process.torch_height.simulated_pipe (the pipe) or process.torch_height (the arc).
    const auto refuse = [&s](const Outcome& o, const char* prefix) {
        const std::string field = o.message.substr(0, o.message.find(' '));
        s.problem_key = std::string(prefix) + field;
        s.problem = std::string(prefix) + o.message;
    };
    if (const Outcome o = checkPipeDefects(s.pipe); !o.ok())
        refuse(o, "process.torch_height.simulated_pipe.");
    else if (const Outcome a = checkArcModelSpec(s.arc); !a.ok())
        refuse(a, "process.torch_height.");
    return s;
}

RobotTorchHeight::RobotTorchHeight(const PipeRobot& robot, const RobotTorchHeightSetup& setup)
    : robot_(robot), setup_(setup), ctl_(setup.thc) {}

void RobotTorchHeight::start(const SourceInput&) {
    ctl_.reset();
    haveLast_ = false;
    delta_.setZero();
    whole_ = {};
    active_ = {};
    maxCorrection_ = 0;
    voltageSamples_ = 0;
}

void RobotTorchHeight::update(const SourceInput& in, bool tool_on, SourceOutput& out) {
    const ArmVector q = out.position.segment<kArmJointCount>(1);
    const Pose tool = robot_.forward(q);
    const Vec3 tip = tool.translation();
    const Vec3 axis = tool.linear().col(2); // the torch axis, into the material
    // The path's speed: the planned tool point relative to the turning pipe.
    const Vec3 onWork = robot_.workFromBase(out.position[0], tip);
    const double speed = haveLast_ ? (onWork - lastWork_).norm() / in.period_s : 0;
    lastWork_ = onWork;
    haveLast_ = true;

    const SensorReading& v = (*in.sensors)[static_cast<size_t>(kArcVoltageSensor)];
    const bool arc = tool_on && in.tool_ok && v.valid && std::isfinite(v.position);
    const ThcOutput& o =
        ctl_.update({.period_s = in.period_s,
                     .arc_ok = arc,
                     .moving = speed > 0,
                     .arc_voltage_v = arc ? v.position : 0,
                     .path_speed_mm_s = speed,
                     .cut_speed_mm_s = setup_.cut_speed_mm_s * in.override_fraction});
    // The correction in joints: the tip moved along the torch axis, the same axis and roll.
    // Where the moved tip has no solution the last correction is held (no jump).
    ArmVector delta = delta_;
    if (o.correction_mm == 0) {
        delta.setZero();
    } else {
        const IkResult r = robot_.solve(tip + o.correction_mm * axis, axis, q[4], &q);
        if (r.ok()) delta = r.q - q;
    }
    out.position.segment<kArmJointCount>(1) += delta;
    out.velocity.segment<kArmJointCount>(1) += (delta - delta_) / in.period_s;
    delta_ = delta;

    ProcessSignals& p = out.process;
    p.present = true;
    p.arc_ok = arc;
    p.thc_enabled = setup_.thc.enabled;
    p.thc_state = static_cast<std::uint8_t>(o.state);
    p.arc_voltage_v = arc ? o.voltage_v : 0;
    p.height_error_mm = arc ? o.height_error_mm : 0;
    p.standoff_mm = arc ? setup_.process.cut_height_mm + o.height_error_mm : 0;
    p.correction_mm = o.correction_mm;

    if (arc && speed > 0 && out.status == SourceStatus::Working) {
        whole_.add(o.height_error_mm);
        if (o.state == ThcState::Active) active_.add(o.height_error_mm);
        maxCorrection_ = std::max(maxCorrection_, std::fabs(o.correction_mm));
        minVoltage_ = voltageSamples_ == 0 ? o.voltage_v : std::min(minVoltage_, o.voltage_v);
        maxVoltage_ = voltageSamples_ == 0 ? o.voltage_v : std::max(maxVoltage_, o.voltage_v);
        ++voltageSamples_;
    }
}

void RobotTorchHeight::fill(TrackingReport& report) const {
    TorchHeightFigures& h = report.torch_height;
    h.valid = true;
    h.thc_on = setup_.thc.enabled;
    h.cut_height_mm = setup_.process.cut_height_mm;
    h.samples = whole_.count;
    h.min_error_mm = whole_.min_mm;
    h.max_error_mm = whole_.max_mm;
    h.max_abs_error_mm = whole_.max_abs_mm;
    h.rms_error_mm = whole_.rms();
    h.active_samples = active_.count;
    h.active_max_abs_error_mm = active_.max_abs_mm;
    h.active_rms_error_mm = active_.rms();
    h.max_abs_correction_mm = maxCorrection_;
    h.min_voltage_v = minVoltage_;
    h.max_voltage_v = maxVoltage_;
}

} // namespace cutcell
