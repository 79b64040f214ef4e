#include "devices/sim/follower_rig.h"

#include <cmath>

namespace cutcell {

CamTable feedStrokeCam(double stroke_mm, double period_mm, int points) {
    CamTable t;
    t.count = points;
    t.period = period_mm;
    for (int i = 0; i < points; ++i) {
        const double u = static_cast<double>(i) / (points - 1);
        t.slave[static_cast<size_t>(i)] = 0.5 * stroke_mm * (1 - std::cos(2 * kPi * u));
    }
    return t;
}

namespace {
// A linear axis of about 1 kg (N, mm, s): PID bandwidth ~100 rad/s, like the robot's joints.
SimulatedDriveConfig linearAxis(double period_s) {
    SimulatedDriveConfig c;
    c.gains.kp = 10.8;
    c.gains.ki = 216;
    c.gains.kd = 0.175;
    c.gains.tau_f = 0.002;
    c.plant.inertia_kg_m2 = 0.001;
    c.plant.viscous_nm_s_per_rad = 0.005;
    c.plant.torque_limit_nm = 50;
    c.period_s = period_s;
    return c;
}
} // namespace

FollowerRig::FollowerRig(const FollowerRigOptions& o)
    : o_(o), line_(o.line), carriage_(std::make_unique<SimulatedDrive>(linearAxis(o.period_s))),
      feed_(std::make_unique<SimulatedDrive>(linearAxis(o.period_s))), saw_(o.saw_spinup_s) {
    MasterFollowerConfig f = o.follower;
    f.master_sensor = 0;
    f.couplings[0].kind = CouplingKind::Gear;
    f.couplings[0].ratio = 1;
    f.couplings[0].slave_sync = f.wait_position[0] + f.start_distance * 0.5;
    f.couplings[1].kind = CouplingKind::Cam;
    f.couplings[1].cam = 0;
    f.couplings[1].cam_offset = f.wait_position[1];
    follower_ = std::make_shared<MasterFollower>(f);
    follower_->camTables().frontForSetup()[0] = feedStrokeCam(o.feed_stroke_mm, o.cam_period_mm);

    auto p = std::make_shared<MotionProgram>();
    p->method = "master_follower";
    p->source_kind = MotionSourceKind::MasterAxis;
    p->source = follower_;
    p->axis_count = 2;
    p->axis_names = {"carriage", "saw feed"};
    p->axis_linear = {true, true};
    p->start_position = f.wait_position;
    p->reference = f.wait_position;
    p->sensors_used = 1u;
    p->name = "follower rig";
    program_ = p;
}

EngineDevices FollowerRig::devices() {
    EngineDevices d;
    d.axes[0] = carriage_.get();
    d.axes[1] = feed_.get();
    d.sensors[0] = &line_;
    d.torch = &saw_;
    return d;
}

void FollowerRig::configure(EngineConfig& config) const {
    config.period_s = o_.period_s;
    config.in_position_window = 1e-6; // mm
    config.in_position_velocity = 1e-4;
}

} // namespace cutcell
