// Range and consistency checks of a job. Each message names the key, the value with its
// unit and the limit it breaks, so the form or the CLI can show it as it is.
#include "core/job/job_io.h"

#include <cmath>
#include <cstdio>

namespace cutcell {
namespace {

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

class Checker {
  public:
    std::vector<JobIssue> issues;

    void add(const std::string& key, const std::string& msg) { issues.push_back({key, msg}); }

    void finite(const std::string& key, double v, const char* unit) {
        if (!std::isfinite(v))
            add(key, key + " = " + num(v) + " " + unit + " is not a finite number");
    }
    void positive(const std::string& key, double v, const char* unit) {
        if (!(v > 0)) add(key, key + " = " + num(v) + " " + unit + " must be > 0 " + unit);
    }
    void nonNegative(const std::string& key, double v, const char* unit) {
        if (!(v >= 0)) add(key, key + " = " + num(v) + " " + unit + " must be >= 0 " + unit);
    }
    void range(const std::string& key, double v, double lo, double hi, const char* unit) {
        if (!(v >= lo && v <= hi))
            add(key, key + " = " + num(v) + " " + unit + " is outside [" + num(lo) + ", " +
                         num(hi) + "] " + unit);
    }
};

void checkPipe(Checker& c, const std::string& name, const PipeSpec& p) {
    c.positive(name + ".radius_mm", p.radius_mm, "mm");
    c.positive(name + ".wall_mm", p.wall_mm, "mm");
    c.positive(name + ".length_mm", p.length_mm, "mm");
    if (p.wall_mm > 0 && p.radius_mm > 0 && p.wall_mm >= p.radius_mm)
        c.add(name + ".wall_mm", name + ".wall_mm = " + num(p.wall_mm) + " mm must be less than " +
                                     name + ".radius_mm = " + num(p.radius_mm) + " mm");
}

// The other branches at the joint (seed 002's several pipes) and the 2-axis machine's drives.
void checkProfileCutter(Checker& c, const Job& job) {
    const double R = job.main_pipe.radius_mm;
    const double a = deg2rad(job.angle_deg);
    for (size_t i = 0; i < job.other_branches.size(); ++i) {
        const OtherBranch& o = job.other_branches[i];
        const std::string k = "other_branches[" + std::to_string(i) + "]";
        c.positive(k + ".radius_mm", o.radius_mm, "mm");
        if (!(o.angle_deg > 0 && o.angle_deg < 180))
            c.add(k + ".angle_deg", k + ".angle_deg = " + num(o.angle_deg) +
                                        " deg is outside (0, 180) deg (angle to the main axis)");
        c.finite(k + ".eccentricity_mm", o.eccentricity_mm, "mm");
        c.finite(k + ".position_mm", o.position_mm, "mm");
        c.finite(k + ".phase_deg", o.phase_deg, "deg");
        const double fit = std::fabs(o.eccentricity_mm) + o.radius_mm;
        if (R > 0 && o.radius_mm > 0 && fit > R)
            c.add(k + ".radius_mm",
                  k + ".radius_mm = " + num(o.radius_mm) +
                      " mm does not fit: |eccentricity_mm| + radius = " + num(fit) +
                      " mm must be <= main_pipe.radius_mm = " + num(R) + " mm");
        // Axes must not be parallel to the cut branch's: the crossing would be undefined.
        const double aj = deg2rad(o.angle_deg), ph = deg2rad(o.phase_deg);
        const double cosAxes =
            std::sin(a) * std::cos(ph) * std::sin(aj) + std::cos(a) * std::cos(aj);
        const double between = rad2deg(std::acos(std::min(1.0, std::fabs(cosAxes))));
        if (std::isfinite(between) && between < 1.0)
            c.add(k + ".angle_deg",
                  k + ": its axis is " + num(between) +
                      " deg from the cut branch's axis; it must differ by >= 1 deg");
    }
    if (job.machine != "profile_cutter_2axis") return;
    const ProfileCutterSpec& p = job.profile_cutter;
    c.range("profile_cutter.steps_per_rev_a", p.steps_per_rev_a, 8, 100000, "steps/rev");
    c.range("profile_cutter.pulses_per_step_a", p.pulses_per_step_a, 1, 100000, "pulses/step");
    c.range("profile_cutter.mm_per_pulse_x", p.mm_per_pulse_x, 1e-5, 1, "mm/pulse");
    c.range("profile_cutter.max_pulse_rate_hz", p.max_pulse_rate_hz, 1, 1e7, "Hz");
    c.range("profile_cutter.pierce_s", p.pierce_s, 0, 60, "s");
    c.range("profile_cutter.x_travel_mm", p.x_travel_mm, 1, 100000, "mm");
    if (!p.branch_position_auto)
        c.range("profile_cutter.branch_position_mm", p.branch_position_mm, 0,
                job.main_pipe.length_mm, "mm");
    // The torch stands radially over the pipe: this machine cannot tilt it for a bevel.
    if (job.cut.bevel_deg != 0)
        c.add("cut.bevel_deg", "cut.bevel_deg = " + num(job.cut.bevel_deg) +
                                   " deg: the 2-axis profile cutter cuts square only (0 deg)");
}

} // namespace

std::vector<JobIssue> validateJob(const Job& job) {
    Checker c;
    if (job.machine != "pipe_robot_6axis" && job.machine != "profile_cutter_2axis")
        c.add("machine", "machine = \"" + job.machine +
                             "\" is not one of \"pipe_robot_6axis\", \"profile_cutter_2axis\"");
    checkPipe(c, "main_pipe", job.main_pipe);
    checkPipe(c, "branch_pipe", job.branch_pipe);
    if (!(job.angle_deg > 0 && job.angle_deg <= 90))
        c.add("angle_deg", "angle_deg = " + num(job.angle_deg) +
                               " deg is outside (0, 90] deg (angle between the pipe axes)");
    c.finite("eccentricity_mm", job.eccentricity_mm, "mm");
    const double fit = std::fabs(job.eccentricity_mm) + job.branch_pipe.radius_mm;
    if (job.main_pipe.radius_mm > 0 && job.branch_pipe.radius_mm > 0 &&
        fit > job.main_pipe.radius_mm)
        c.add("branch_pipe.radius_mm",
              "branch_pipe.radius_mm = " + num(job.branch_pipe.radius_mm) +
                  " mm does not fit: |eccentricity_mm| + branch radius = " + num(fit) +
                  " mm must be <= main_pipe.radius_mm = " + num(job.main_pipe.radius_mm) + " mm");

    c.range("cut.bevel_deg", job.cut.bevel_deg, -60, 60, "deg");
    c.positive("cut.speed_mm_s", job.cut.speed_mm_s, "mm/s");
    if (job.cut.speed_mm_s > 500)
        c.add("cut.speed_mm_s", "cut.speed_mm_s = " + num(job.cut.speed_mm_s) +
                                    " mm/s is above the limit of 500 mm/s");
    c.range("cut.ramp_s", job.cut.ramp_s, 0.01, 10, "s");
    c.range("cut.max_direction_deviation_deg", job.cut.max_direction_deviation_deg, 0, 90, "deg");
    c.range("cut.knot_spacing_mm", job.cut.knot_spacing_mm, 0.05, 20, "mm");
    if (!job.cut.start_phi_auto)
        c.range("cut.start_phi_deg", job.cut.start_phi_deg, -360, 360, "deg");
    c.range("cut.static_chuck_deg", job.cut.static_chuck_deg, -180, 180, "deg");

    for (int i = 0; i < kAxisCount; ++i) {
        const auto& d = job.dh[static_cast<size_t>(i)];
        const std::string k = "robot.dh[" + std::to_string(i) + "]";
        c.finite(k + ".alpha_deg", d.alpha_deg, "deg");
        c.finite(k + ".a_mm", d.a_mm, "mm");
        c.finite(k + ".d_mm", d.d_mm, "mm");
        c.range(k + ".min_deg", d.min_deg, -360, 360, "deg");
        c.range(k + ".max_deg", d.max_deg, -360, 360, "deg");
        if (d.min_deg >= d.max_deg)
            c.add(k + ".min_deg", k + ".min_deg = " + num(d.min_deg) + " deg must be below " + k +
                                      ".max_deg = " + num(d.max_deg) + " deg");
    }
    // The analytic IK is written for the seed's arm structure (alpha = 90, 0, 0, 90, 0).
    const double structure[kAxisCount] = {90, 90, 0, 0, 90, 0};
    for (int i = 1; i < kAxisCount; ++i) {
        const auto& d = job.dh[static_cast<size_t>(i)];
        if (std::fabs(d.alpha_deg - structure[i]) > 1e-9)
            c.add("robot.dh[" + std::to_string(i) + "].alpha_deg",
                  "robot.dh[" + std::to_string(i) + "].alpha_deg = " + num(d.alpha_deg) +
                      " deg: the pipe robot's inverse kinematics needs " + num(structure[i]) +
                      " deg");
    }
    // ... and for its offsets: these lengths are zero on the seed's arm.
    const struct {
        int row;
        const char* field;
        double value;
    } zeros[] = {{1, "a_mm", job.dh[1].a_mm},
                 {2, "d_mm", job.dh[2].d_mm},
                 {3, "d_mm", job.dh[3].d_mm},
                 {4, "d_mm", job.dh[4].d_mm},
                 {5, "a_mm", job.dh[5].a_mm}};
    for (const auto& z : zeros)
        if (std::fabs(z.value) > 1e-9) {
            const std::string k = "robot.dh[" + std::to_string(z.row) + "]." + z.field;
            c.add(k,
                  k + " = " + num(z.value) + " mm: the pipe robot's inverse kinematics needs 0 mm");
        }
    if (job.dh[2].a_mm <= 0 || job.dh[3].a_mm <= 0)
        c.add("robot.dh[2].a_mm",
              "robot.dh[2].a_mm and robot.dh[3].a_mm must be > 0 mm (arm links)");

    for (int i = 0; i < kAxisCount; ++i) {
        const auto& g = job.controller[static_cast<size_t>(i)];
        const std::string k = "controller[" + std::to_string(i) + "]";
        c.nonNegative(k + ".kp_nm_per_rad", g.kp, "N m/rad");
        c.nonNegative(k + ".ki_nm_per_rad_s", g.ki, "N m/(rad s)");
        c.nonNegative(k + ".kd_nm_s_per_rad", g.kd, "N m s/rad");
        c.positive(k + ".tau_f_s", g.tau_f, "s");
        const auto& p = job.plant[static_cast<size_t>(i)];
        const std::string pk = "plant[" + std::to_string(i) + "]";
        c.positive(pk + ".inertia_kg_m2", p.inertia_kg_m2, "kg m^2");
        c.nonNegative(pk + ".viscous_nm_s_per_rad", p.viscous_nm_s_per_rad, "N m s/rad");
        c.positive(pk + ".torque_limit_nm", p.torque_limit_nm, "N m");
    }

    c.range("sim.period_s", job.sim.period_s, 1e-4, 0.02, "s");
    c.range("sim.duration_s", job.sim.duration_s, 0.1, 3600, "s");
    // The filter time constant must be resolvable at the control period.
    for (int i = 0; i < kAxisCount; ++i) {
        const auto& g = job.controller[static_cast<size_t>(i)];
        if (g.tau_f > 0 && job.sim.period_s > 0 && g.tau_f < job.sim.period_s / 2)
            c.add("controller[" + std::to_string(i) + "].tau_f_s",
                  "controller[" + std::to_string(i) + "].tau_f_s = " + num(g.tau_f) +
                      " s must be >= half the control period (" + num(job.sim.period_s / 2) +
                      " s)");
    }

    c.range("engine.feed_hold_decel_s", job.engine.feed_hold_decel_s, 0.01, 10, "s");
    c.range("engine.following_error_limit_deg", job.engine.following_error_limit_deg, 0.001, 90,
            "deg");
    c.range("engine.home_speed_deg_s", job.engine.home_speed_deg_s, 0.1, 360, "deg/s");
    if (job.devices.bitrate_bps <= 0)
        c.add("devices.bitrate_bps",
              "devices.bitrate_bps = " + std::to_string(job.devices.bitrate_bps) +
                  " bit/s must be > 0 bit/s");
    for (int i = 0; i < kAxisCount; ++i) {
        const int id = job.devices.node_ids[static_cast<size_t>(i)];
        if (id < 1 || id > 127)
            c.add("devices.node_ids", "devices.node_ids[" + std::to_string(i) +
                                          "] = " + std::to_string(id) + " is outside [1, 127]");
        for (int j = 0; j < i; ++j)
            if (job.devices.node_ids[static_cast<size_t>(j)] == id)
                c.add("devices.node_ids", "devices.node_ids[" + std::to_string(i) +
                                              "] = " + std::to_string(id) + " is used twice");
        c.positive("devices.counts_per_unit[" + std::to_string(i) + "]",
                   job.devices.counts_per_unit[static_cast<size_t>(i)], "counts/deg");
    }
    c.range("devices.heartbeat_timeout_ms", job.devices.heartbeat_timeout_ms, 10, 10000, "ms");
    checkProfileCutter(c, job);
    return c.issues;
}

} // namespace cutcell
