#include "devices/sim/slider_rig.h"

namespace cutcell {

namespace {
SimulatedTorqueDriveConfig sliderDrive(const SliderRigOptions& o) {
    SimulatedTorqueDriveConfig c;
    c.plant.inertia_kg_m2 = 0.005;               // 5 kg in N / (mm/s^2)
    c.plant.viscous_nm_s_per_rad = 0.02;         // N s/mm
    c.plant.torque_limit_nm = o.law.force_limit; // N
    c.period_s = o.period_s;
    c.initial_position = o.law.stroke_from;
    return c;
}
} // namespace

SliderRig::SliderRig(const SliderRigOptions& o)
    : o_(o), drive_(sliderDrive(o)), sensor_(drive_, o.sensor_resolution_mm) {
    PdSliderLawConfig lc = o.law;
    lc.axis = 0;
    lc.sensor = 0;
    law_ = std::make_shared<PdSliderLaw>(lc);
    auto p = std::make_shared<MotionProgram>();
    p->method = "control_law";
    p->source_kind = MotionSourceKind::ControlLaw;
    p->source = law_;
    p->axis_count = 1;
    p->axis_names = {"slider"};
    p->axis_linear = {true};
    p->axis_modes[0] = AxisCommandMode::Torque;
    p->reference[0] = lc.stroke_from;
    p->start_position[0] = lc.stroke_from;
    p->min_position[0] = lc.stroke_from - 2 * lc.catch_distance;
    p->max_position[0] = lc.stroke_to + lc.catch_distance;
    p->sensors_used = 1u;
    p->uses_tool = false;
    p->name = "slider rig";
    program_ = p;
}

EngineDevices SliderRig::devices() {
    EngineDevices d;
    d.axes[0] = &drive_;
    d.sensors[0] = &sensor_;
    return d;
}

void SliderRig::configure(EngineConfig& config) const {
    config.period_s = o_.period_s;
    config.in_position_window = 0.05; // mm: a PD on a quantised sensor
    config.in_position_velocity = 1;  // mm/s
    // A force moves the slider only after a cycle or two while the law's reference already
    // runs at stroke speed (0.1 mm per cycle): frozen means no change over 0.5 mm of travel.
    config.frozen_feedback_travel = 0.5;
}

} // namespace cutcell
