#pragma once
// The mechanics of the seed-000 cell behind its six drives: either six linear joint plants (the
// job's plant[] rows) or the arm as coupled rigid bodies (core/dynamics/chain_dynamics.h) and the
// chuck turning the pipe, with each joint's gear, rotor inertia, viscous and Coulomb friction and
// torque limit (robot.links[], robot.drives[], robot.chuck). The offline simulation, the
// simulated drives of the operator station and the drive simulator on CAN all run this one.
//
// Rigid body: the state is integrated over each control period with the torques held
// (zero-order hold), in `substeps` equal steps; Coulomb friction is applied after each step as an
// impulse that can stop a joint but never reverse it (time stepping as in Moreau's method), so
// that friction needs no smoothing and no stiff step. Gravity is -Z0.
//
// Two integrators of fourth order (RigidIntegrator):
// - Runge-Kutta (RK4): four forward-dynamics evaluations per step.
// - Adams-Nystrom (explicit, 4 steps): one evaluation per step, at the step's start; the three
//   before it are reused. Because the torque changes from one period to the next, each stored
//   acceleration is brought to the step's torque through its own mass matrix's Cholesky factor
//   (a_j + M_j^-1 (tau - tau_j): two triangular solves), so the method integrates the ODE with
//   the torque the step holds. It starts (and restarts after setState or a brake change) with
//   three RK4 steps. Its stability interval is 10x shorter than RK4's: Auto takes it only where
//   h * (viscous / inertia) <= 0.1 on every axis (a third of its limit 0.3; the joints' reflected
//   rotor inertias bound M from below), else RK4.
//   Error: tests/core/chain_dynamics_test.cpp measures both against RK4 at 32 substeps.
#include "core/control/coupled_mechanics.h"
#include "core/control/joint_plant.h"
#include "core/dynamics/chain_dynamics.h"
#include "core/job/job.h"
#include "core/machines/pipe_robot/arm_dynamics_spec.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"

#include <array>
#include <string>

namespace cutcell {

inline constexpr double kStandardGravity = 9.80665;

// The arm's chain (joints 1..5) as the dynamics see it, from a job's robot section.
ChainDynamics pipeRobotArmDynamics(const PipeRobotSpec& spec);
// The chuck axis's inertia about the pipe axis (kg m^2): chuck, pipe in it, reflected rotor.
double pipeRobotChuckInertia(const Job& job);

// Why a link's inertia tensor is not one of a real body ("" if it is): its principal moments
// must be >= 0 and each at most the sum of the other two.
std::string inertiaTensorProblem(const ArmLinkRow& link);

enum class RigidIntegrator { Auto, RungeKutta4, AdamsNystrom4 };
const char* integratorName(RigidIntegrator integrator);

class PipeRobotMechanics : public CoupledMechanics {
  public:
    PipeRobotMechanics() = default;
    PipeRobotMechanics(const Job& job, double period_s, int substeps = 1,
                       RigidIntegrator integrator = RigidIntegrator::Auto) {
        configure(job, period_s, substeps, integrator);
    }
    void configure(const Job& job, double period_s, int substeps = 1,
                   RigidIntegrator integrator = RigidIntegrator::Auto);
    // The integrator the rigid-body plant runs (Auto resolved).
    RigidIntegrator integrator() const { return integrator_; }
    // Positions (rad), at rest.
    void setState(const JointVector& q);
    void setState(const JointVector& q, const JointVector& qd);

    PlantModel model() const { return model_; }
    int axisCount() const override { return kAxisCount; }
    double position(int axis) const override { return q_[axis]; }
    double velocity(int axis) const override { return v_[axis]; }
    double torqueLimit(int axis) const override { return limit_[static_cast<size_t>(axis)]; }
    void step(const JointVector& torque, JointVector& applied) override;
    void setHeld(int axis, bool held) override;
    double holdingTorque(int axis) const override;
    // g(q) of the six axes at positions q (0 for the chuck and for the linear plant).
    void gravityTorques(const JointVector& q, JointVector& tau) const;

    const ChainDynamics& arm() const { return arm_; }
    double chuckInertia() const { return chuckInertia_; }
    // Total mechanical energy (kinetic + potential, J) of the rigid-body state.
    double energy() const;

  private:
    using Vec = ChainDynamics::Vector;
    using Factor = ChainDynamics::CholeskyFactor;
    // q'' of all six axes for a state and held torques (friction: viscous only); optionally the
    // arm's mass-matrix diagonal and Cholesky factor at q. False where M is singular (the arm's
    // q'' is then 0 and the factor unfinished).
    bool acceleration(const JointVector& q, const JointVector& v, const JointVector& tau,
                      JointVector& a, double* armMassDiagonal, Factor* armCholesky) const;
    void rigidStep(const JointVector& tau, double h);
    // One step of each integrator from (q_, v_); a0 = q'' at (q_, v_, tau).
    void rungeKuttaStep(const JointVector& tau, double h, const JointVector& a0);
    void adamsNystromStep(const JointVector& tau, double h, const JointVector& a0);
    // The stored acceleration `back` steps ago, brought to the torque tau, added with weights
    // to the sums for v and q.
    void addPastAcceleration(int back, const JointVector& tau, double weightV, double weightQ,
                             JointVector& sumV, JointVector& sumQ) const;
    void applyCoulomb(double h, const double* armMassDiagonal);
    void clearHistory() { historySize_ = 0; }

    // The last accelerations (the newest at historyHead_), with the torque and the arm's
    // Cholesky factor each was computed with.
    static constexpr int kHistory = 3, kRing = kHistory + 1; // + the step being made
    struct PastStep {
        JointVector a = JointVector::Zero();
        JointVector tau = JointVector::Zero();
        Factor cholesky{};
    };
    std::array<PastStep, kRing> history_{};
    int historyHead_ = 0, historySize_ = 0;
    RigidIntegrator integrator_ = RigidIntegrator::RungeKutta4;

    PlantModel model_ = PlantModel::Linear;
    double period_ = 0.001;
    int substeps_ = 1;
    std::array<JointPlant, kAxisCount> linear_{};
    ChainDynamics arm_;
    double chuckInertia_ = 0;
    std::array<double, kAxisCount> limit_{}, viscous_{}, coulomb_{};
    std::array<bool, kAxisCount> held_{};
    JointVector q_ = JointVector::Zero(), v_ = JointVector::Zero();
};

} // namespace cutcell
