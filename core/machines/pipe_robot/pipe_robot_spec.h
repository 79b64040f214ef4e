#pragma once
// The pipe robot's own part of a job (its struct in Job::machine_spec, see
// core/job/machine_spec.h): the cut method, the DH table of the chuck and the arm, and per axis
// the drive's PID gains and the joint plant. The pipe joint it cuts (main_pipe, branch_pipe,
// angle_deg, eccentricity_mm, cut) is shared with the profile cutter and read by
// core/machine/pipe_joint_section.h.
#include "core/job/job.h"
#include "core/job/machine_spec.h"
#include "core/job/row_table.h"
#include "core/machines/pipe_robot/arm_dynamics_spec.h"

#include <array>
#include <span>

namespace cutcell {

// The robot's axes: axis 0 is the pipe chuck (the seed's theta0); axes 1..5 are the arm joints
// theta1..theta5.
inline constexpr int kAxisCount = 6;
inline constexpr int kArmJointCount = 5;

enum class CutMethod { StaticPipe, RotatingPipe };
const char* toString(CutMethod m);

// One standard Denavit-Hartenberg row with its operating range. Row 0 is the pipe chuck:
// its d is the seed's d0 (distance from the robot base to the pipe's cut centre along X0).
struct DhRow {
    double alpha_deg = 0;
    double a_mm = 0;
    double d_mm = 0;
    double theta_offset_deg = 0;
    double min_deg = -180;
    double max_deg = 180;
};

// The seed's Table 1 (row 0 = chuck with d0, rows 1..5 = the arm).
std::array<DhRow, kAxisCount> seedDhTable();
// The keys of a robot.dh[] row, in the file's order (the physical ranges; min below max, the
// reference 0 deg and the arm's structure are checked by the module's validate()).
std::span<const RowField<DhRow>> dhRowFields();

struct PipeRobotSpec : MachineSpecOf<PipeRobotSpec> {
    CutMethod method = CutMethod::RotatingPipe;
    std::array<DhRow, kAxisCount> dh = seedDhTable();
    std::array<PidGains, kAxisCount> controller{};
    std::array<JointPlantParams, kAxisCount> plant{};
    // The mechanics the simulated drives run (plant_model) and, for the rigid-body plant, the
    // arm's links, the axes' drive trains and the chuck (arm_construction.h has the defaults).
    PlantModel plant_model = PlantModel::RigidBody;
    bool gravity_feedforward = false;
    std::array<ArmLinkRow, kArmJointCount> links = defaultArmLinks();
    std::array<DriveTrainRow, kAxisCount> drives = defaultDrives();
    ChuckLoad chuck = defaultChuck();

  private:
    static std::array<ArmLinkRow, kArmJointCount> defaultArmLinks();
    static std::array<DriveTrainRow, kAxisCount> defaultDrives();
    static ChuckLoad defaultChuck();
};

// The robot's section of a job. A job that holds no section yet (one being built in code,
// Job{}) reads as the default one, and the non-const form gives it that one to edit; a job
// holding another machine's section throws std::invalid_argument.
const PipeRobotSpec& pipeRobotSpec(const Job& job);
PipeRobotSpec& pipeRobotSpec(Job& job);

} // namespace cutcell
