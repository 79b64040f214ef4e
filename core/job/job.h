#pragma once
// The cutting job: everything an engineer sets up for one cut. Values carry SI-ish units
// named in their JSON keys (mm, deg, s, mm/s); see resources/jobs/default_job.json.
#include "core/common/types.h"
#include "core/job/machine_spec.h"
#include "core/process/process_spec_data.h"

#include <array>
#include <string>
#include <vector>

namespace cutcell {

enum class CutTarget { Branch, Main };
enum class StopCategory { Cat0, Cat1 };
enum class DeviceKind { Simulated, CanOpen };

struct PipeSpec {
    double radius_mm = 0;
    double wall_mm = 0;
    double length_mm = 0;
};

// PID with first-order filter (seed Eq. 69): C(s) = (Kd s + Kp + Ki/s) / (tau_f s + 1).
// Output is a joint torque (N m) from a joint error (rad).
struct PidGains {
    double kp = 0;    // N m / rad
    double ki = 0;    // N m / (rad s)
    double kd = 0;    // N m s / rad
    double tau_f = 0; // s
};

// Joint plant seen from the joint side of the gearbox: J q'' + b q' = clamp(u, +-u_max).
struct JointPlantParams {
    double inertia_kg_m2 = 0;
    double viscous_nm_s_per_rad = 0;
    double torque_limit_nm = 0;
};

struct CutSpec {
    CutTarget target = CutTarget::Main;
    double bevel_deg = 0;
    double speed_mm_s = 0;
    // Time to accelerate from rest to the cutting speed (and to stop at the end).
    double ramp_s = 0.5;
    // A 5-DOF arm can only point its torch within the plane of joint 1; the planner tilts the
    // torch into that plane and refuses the path when the tilt exceeds this limit.
    double max_direction_deviation_deg = 25;
    // Knot spacing of the joint-space spline along the cut.
    double knot_spacing_mm = 1.0;
    // Chuck angle held during the static-pipe method.
    double static_chuck_deg = 0;
    // Where the closed cut starts (the curve parameter phi). Absent in the file = automatic:
    // -90 deg for the hole (the chuck stands still there, so the start ramp disturbs nothing)
    // and -180 deg for the branch end (its full turn of the chuck then stays within +-180 deg).
    bool start_phi_auto = true;
    double start_phi_deg = 0;
};

struct SimSpec {
    double period_s = 0.001;
    double duration_s = 30;
};

struct EngineSpec {
    StopCategory estop_category = StopCategory::Cat0;
    double feed_hold_decel_s = 0.5; // time to stop along the path on feed hold
    bool torch_on_during_feed_hold = false;
    // Following-error limit and homing / jog / approach speed, each in the unit of the axes it
    // governs: rotary axes in deg and deg/s, linear axes in mm and mm/s.
    double following_error_limit_deg = 2.0;
    double home_speed_deg_s = 20.0;
    double following_error_limit_mm = 2.0;
    double home_speed_mm_s = 20.0;
    std::string runs_dir = "runs";
};

// The CAN drives of the machine: one node id and one encoder scaling per axis of the machine
// (MachineModule::axes(), up to kMaxAxes; the file holds exactly that many, or 6 as files did
// when every machine had 6 slots), and one node id per external sensor the machine reads
// (MachineModule::sensorNames(): CiA 406 encoders; 0 = the next ids after the axes').
inline constexpr int kMaxDeviceSensors = 4;
struct DeviceSpec {
    DeviceKind kind = DeviceKind::Simulated;
    std::string can_plugin = "virtualcan";
    std::string can_interface = "can0";
    int bitrate_bps = 1000000;
    std::array<int, kMaxAxes> node_ids{1, 2, 3, 4, 5, 6, 7, 8};
    // Counts per degree (or per mm for linear axes) of each drive's position encoder.
    std::array<double, kMaxAxes> counts_per_unit{1000, 1000, 1000, 1000, 1000, 1000, 1000, 1000};
    std::array<int, kMaxDeviceSensors> sensor_node_ids{};
    double heartbeat_timeout_ms = 300;
    // CiA 301 0x1019: the SYNC carries a counter 1..this (written to every node), which the
    // drives check; 0 for nodes without the object (SYNC without a counter).
    int sync_counter_overflow = 240;
};

// The node id of the machine's sensor k (sensor_node_ids[k], or axisCount + 1 + k when 0).
int sensorNodeId(const DeviceSpec& d, int axisCount, int k);

// The common part (name, description, units note, sim, engine, devices), the pipe joint the
// pipe machines cut (pipes, angle, eccentricity, cut; core/machine/pipe_joint_section.h), and
// the machine's own section in machine_spec. Each module reads, writes and validates only its
// own (core/machines/<name>/). machine = the id of the job's module ("" = the schema-1 default
// machine).
struct Job {
    int schema = 2;
    std::string machine;
    std::string name;
    std::string description;
    std::string units_note; // free text: how the keys name their units
    PipeSpec main_pipe;
    PipeSpec branch_pipe;
    double angle_deg = 90;
    double eccentricity_mm = 0;
    CutSpec cut;
    // The cutting process of a torch machine (core/process/process_spec.h): the cut chart's
    // entry and the operator's overrides; unused (process.used false) on the other machines.
    ProcessSpec process;
    SimSpec sim;
    EngineSpec engine;
    DeviceSpec devices;
    // The machine's own section (core/machines/<name>/<name>_spec.h): set by the module's
    // defaultJob() and readSection(), read back with machine_spec.as<TheirSpec>().
    MachineSpecHolder machine_spec;
};

const char* toString(CutTarget t);
const char* toString(DeviceKind k);
const char* toString(StopCategory c);

} // namespace cutcell
