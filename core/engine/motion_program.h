#pragma once
// What the engine runs for a machine: its axes (up to kMaxAxes, each with its unit, limits and
// command mode) and its motion source — a joint trajectory in time with the cut's length and a
// tip model for the Cartesian error, or a master-axis coupling, or a control law (see
// motion_source.h). Built by a machine from a job; the engine knows no machine.
#include "core/common/types.h"
#include "core/devices/device_interfaces.h"
#include "core/engine/motion_source.h"
#include "core/engine/run_terms.h"
#include "core/engine/setpoint_correction.h"
#include "core/kinematics/tip_model.h"
#include "core/trajectory/joint_spline.h"

#include <array>
#include <memory>
#include <string>

namespace cutcell {

// Which motion source runs the program (motion_engine.h says how each one behaves).
enum class MotionSourceKind : std::uint8_t {
    JointSpline, // the joint spline in time (pipe robot, profile cutter)
    MasterAxis,  // coupled to a master axis the engine does not drive (MasterFollower)
    ControlLaw,  // a control law run in the cycle (torque-mode axes)
};
const char* toString(MotionSourceKind k);

struct MotionProgram {
    std::string machine; // the id of the machine module that built it
    std::string method;  // how the machine cuts (e.g. "rotating_pipe"), for reports
    int axis_count = 0;  // axes 0..axis_count-1 are driven (1 .. kMaxAxes; set by the machine)
    std::array<std::string, kMaxAxes> axis_names{};
    std::array<bool, kMaxAxes> axis_linear{}; // mm instead of rad
    // A rotary axis without end stops that turns on and on (the quick-return crank): every
    // whole turn brings it to the same place, so a move to the reference (Home) takes the
    // short way, at most half a turn, instead of unwinding the turns of the last runs.
    std::array<bool, kMaxAxes> axis_continuous{};
    // Command mode of every axis; the drives must be set to it before Load (outside the cycle).
    std::array<AxisCommandMode, kMaxAxes> axis_modes{};
    MotionSourceKind source_kind = MotionSourceKind::JointSpline;
    // MasterAxis / ControlLaw: the source. It keeps run state and is updated by the engine
    // thread of the one engine the program is loaded into.
    std::shared_ptr<MotionSource> source;
    // MasterAxis: where the axes go before the source starts (the approach); ControlLaw: unused
    // (the law starts from where the axes are).
    JointVector start_position = JointVector::Zero();
    // A process control on the set-point while the program runs (the torch height control),
    // after the source each cycle; null for none. Updated by the engine thread only.
    std::shared_ptr<SetpointCorrection> correction;
    std::uint32_t sensors_used = 0; // bit i: EngineDevices::sensors[i] must be present
    bool uses_tool = true;          // the process tool is lit (and awaited) before the motion
    JointSpline spline;             // JointSpline: t = 0 .. cut_time_s, at rest at both ends
    double cut_time_s = 0;
    double length_mm = 0;
    size_t point_count = 0; // knots along the cut (progress: current point / total)
    JointVector reference = JointVector::Zero(); // home position of every axis
    std::shared_ptr<const TipModel> tip_model;   // may be null
    // Operating range of every axis (rad or mm); jogs and the reference are checked against it.
    JointVector min_position = JointVector::Constant(-1e9);
    JointVector max_position = JointVector::Constant(1e9);
    // A continuous axis of a source program: the farthest |position| (rad or mm) one run can
    // take it from 0, by the plan (the saw's turntable: half a turn a piece); 0 = not known.
    // A drive counts positions in 32 bits: core/machine/counts_reach.h checks it.
    JointVector endless_reach = JointVector::Zero();
    // The run lasts at least this long from the first cut sample (the drives keep being
    // tracked after the path's end until then), so its figures cover the same span as the
    // offline simulation (sim.duration_s).
    double min_run_s = 0;
    // After the arc is established at the first cut point the torch dwells this long before
    // the path moves (the G-code's G4 pierce dwell); 0 = move at once.
    double pierce_s = 0;
    // Path-time window of constant cutting speed (the report's "cruise" figures); empty if to <
    // from.
    double cruise_from_s = 0;
    double cruise_to_s = -1;
    // How the run is spoken of (tool, what progress counts, what a run makes): run_terms.h.
    RunTerms terms;
    std::string name; // the job's name, for the run log
    std::string
        source_text; // the job file (JSON) the program was built from: job.json of the run log
};

} // namespace cutcell
