#pragma once
// SIMC tuning of the seed-000 cell's six PID drives (core/control/simc_tuning.h). Each axis is
// seen from its drive as J q'' + b q' = u behind the control period's hold and the PID's own
// filter:
//
//  - rigid-body plant: J = the axis's inertia at the cut's mean configuration - the arm's
//    M_ii(q_mean) (reflected rotor included) from pipeRobotArmDynamics, the chuck's
//    pipeRobotChuckInertia -, b = robot.drives[i].viscous_nm_s_per_rad. q_mean is the time
//    average of the planned cut's joint trajectory (planCut).
//  - linear plant: J and b of plant[i].
//
// Each axis keeps its tau_f; the gains are rounded to the decimals the job file and the forms
// give them (core/job/drive_fields.h).
#include "core/common/outcome.h"
#include "core/common/types.h"
#include "core/control/simc_tuning.h"
#include "core/job/job.h"
#include "core/machine/plan_options.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"

#include <array>
#include <string>

namespace cutcell {

struct PipeRobotAxisTuning {
    std::string axis;    // "theta1"
    SimcTuning simc;     // J, b, theta, tau_c, Kc, tau_I, tau_D and the gains (unrounded)
    LoopMargins margins; // of the rounded gains on the sampled loop
};

struct PipeRobotTuning {
    // Ok, Refused (the job's plan is not feasible: the rigid-body plant needs its poses) or
    // Cancelled (options.cancel).
    Outcome outcome;
    PlantModel model = PlantModel::RigidBody;
    JointVector q_mean = JointVector::Zero(); // rad (rigid body only)
    std::array<PidGains, kAxisCount> gains{}; // rounded, for controller[]
    std::array<PipeRobotAxisTuning, kAxisCount> axes{};
};

// tau_c_s <= 0: SIMC's tight tuning, tau_c = theta. The job must be valid.
PipeRobotTuning tunePipeRobot(const Job& job, double tau_c_s = 0, const PlanOptions& options = {});

// The table for the operator: per axis J, b, theta, Kp, Ki, Kd, tau_f and the loop's margins,
// then one line per axis with the rule and its series figures (C locale).
std::string pipeRobotTuningText(const PipeRobotTuning& t);

} // namespace cutcell
