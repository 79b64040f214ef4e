#include "core/machines/pipe_robot/pipe_robot_mechanics.h"

#include "core/common/c_format.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace cutcell {
namespace {

constexpr double kGramCm2 = 1e-7; // g cm^2 -> kg m^2
constexpr double kKgCm2 = 1e-4;   // kg cm^2 -> kg m^2

double reflectedRotor(const DriveTrainRow& d) {
    return d.gear_ratio * d.gear_ratio * d.rotor_inertia_g_cm2 * kGramCm2;
}

LinkInertia toInertia(const ArmLinkRow& r) {
    LinkInertia l;
    l.mass_kg = r.mass_kg;
    l.com_m = Vec3(r.com_x_mm, r.com_y_mm, r.com_z_mm) * 1e-3;
    l.inertia_kg_m2 << r.ixx_kg_cm2, r.ixy_kg_cm2, r.ixz_kg_cm2, r.ixy_kg_cm2, r.iyy_kg_cm2,
        r.iyz_kg_cm2, r.ixz_kg_cm2, r.iyz_kg_cm2, r.izz_kg_cm2;
    l.inertia_kg_m2 *= kKgCm2;
    return l;
}

} // namespace

const char* integratorName(RigidIntegrator integrator) {
    switch (integrator) {
    case RigidIntegrator::Auto:
        return "auto";
    case RigidIntegrator::RungeKutta4:
        return "Runge-Kutta 4";
    case RigidIntegrator::AdamsNystrom4:
        return "Adams-Nystrom 4";
    }
    return "?";
}

std::string inertiaTensorProblem(const ArmLinkRow& link) {
    const Mat3 I = toInertia(link).inertia_kg_m2 / kKgCm2;
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(I, Eigen::EigenvaluesOnly);
    const Vec3 p = eig.eigenvalues(); // ascending, kg cm^2
    const double tol = 1e-9 * std::max(1.0, p.cwiseAbs().maxCoeff());
    if (p[0] < -tol)
        return messageC("the inertia tensor has a negative principal moment %.6g kg cm^2", p[0]);
    if (p[2] > p[0] + p[1] + tol)
        return messageC("the principal moments %.6g, %.6g, %.6g kg cm^2 break the triangle "
                        "inequality (the largest may be at most the sum of the others)",
                        p[0], p[1], p[2]);
    return {};
}

ChainDynamics pipeRobotArmDynamics(const PipeRobotSpec& spec) {
    std::array<ChainJoint, kArmJointCount> joints{};
    std::array<LinkInertia, kArmJointCount> links{};
    for (int i = 0; i < kArmJointCount; ++i) {
        const auto s = static_cast<size_t>(i);
        const DhRow& r = spec.dh[s + 1];
        joints[s] = {deg2rad(r.alpha_deg), r.a_mm * 1e-3, r.d_mm * 1e-3,
                     deg2rad(r.theta_offset_deg), reflectedRotor(spec.drives[s + 1])};
        links[s] = toInertia(spec.links[s]);
    }
    return ChainDynamics(joints, links, Vec3(0, 0, -kStandardGravity));
}

double pipeRobotChuckInertia(const Job& job) {
    const PipeRobotSpec& spec = pipeRobotSpec(job);
    // The chuck holds the pipe being cut: the main pipe for its hole, the branch for its end.
    const PipeSpec& pipe = job.cut.target == CutTarget::Main ? job.main_pipe : job.branch_pipe;
    const double ro = pipe.radius_mm * 1e-3;
    const double ri = std::max(0.0, ro - pipe.wall_mm * 1e-3);
    const double mass =
        spec.chuck.pipe_density_kg_m3 * kPi * (ro * ro - ri * ri) * pipe.length_mm * 1e-3;
    return spec.chuck.inertia_kg_m2 + 0.5 * mass * (ro * ro + ri * ri) +
           reflectedRotor(spec.drives[0]);
}

void PipeRobotMechanics::configure(const Job& job, double period_s, int substeps,
                                   RigidIntegrator integrator) {
    const PipeRobotSpec& spec = pipeRobotSpec(job);
    model_ = spec.plant_model;
    period_ = period_s;
    substeps_ = std::max(1, substeps);
    held_.fill(false);
    for (int i = 0; i < kAxisCount; ++i) {
        const auto s = static_cast<size_t>(i);
        linear_[s].configure(spec.plant[s], period_s);
        const bool rigid = model_ == PlantModel::RigidBody;
        limit_[s] = rigid ? spec.drives[s].torque_limit_nm : spec.plant[s].torque_limit_nm;
        viscous_[s] = spec.drives[s].viscous_nm_s_per_rad;
        coulomb_[s] = spec.drives[s].coulomb_nm;
    }
    arm_ = pipeRobotArmDynamics(spec);
    chuckInertia_ = pipeRobotChuckInertia(job);
    integrator_ = integrator;
    if (integrator_ == RigidIntegrator::Auto) {
        // The fastest viscous decay rate b / J each axis can have: J is at least the chuck's
        // inertia, or the joint's reflected rotor inertia (M >= diag(N^2 J_rotor)).
        const double h = period_ / substeps_;
        bool stable = true;
        for (int i = 0; i < kAxisCount; ++i) {
            const double b = viscous_[static_cast<size_t>(i)];
            const double J = i == 0 ? chuckInertia_ : arm_.joint(i - 1).rotor_inertia_kg_m2;
            if (b > 0 && !(J > 0 && h * b / J <= 0.1)) stable = false;
        }
        integrator_ = stable ? RigidIntegrator::AdamsNystrom4 : RigidIntegrator::RungeKutta4;
    }
    setState(JointVector::Zero());
}

void PipeRobotMechanics::setHeld(int axis, bool held) {
    bool& h = held_[static_cast<size_t>(axis)];
    if (h != held) clearHistory(); // the stored accelerations were for the other constraint
    h = held;
}

void PipeRobotMechanics::setState(const JointVector& q) {
    setState(q, JointVector::Zero());
}

void PipeRobotMechanics::setState(const JointVector& q, const JointVector& qd) {
    q_ = q;
    v_ = qd;
    clearHistory();
    for (int i = 0; i < kAxisCount; ++i)
        linear_[static_cast<size_t>(i)].setState(q[i], qd[i]);
}

bool PipeRobotMechanics::acceleration(const JointVector& q, const JointVector& v,
                                      const JointVector& tau, JointVector& a,
                                      double* armMassDiagonal, Factor* armCholesky) const {
    a.setZero();
    a[0] = held_[0] ? 0.0 : (tau[0] - viscous_[0] * v[0]) / chuckInertia_;
    Vec qa = Vec::Zero(), va = Vec::Zero(), ta = Vec::Zero(), aa;
    for (int i = 0; i < kArmJointCount; ++i) {
        qa[i] = q[i + 1];
        va[i] = v[i + 1];
        ta[i] = tau[i + 1] - viscous_[static_cast<size_t>(i + 1)] * v[i + 1];
    }
    ChainDynamics::ForwardOptions options;
    for (int i = 0; i < kArmJointCount; ++i)
        if (held_[static_cast<size_t>(i + 1)]) options.held_mask |= 1u << i;
    Vec diagonal;
    if (armMassDiagonal) options.mass_diagonal = &diagonal;
    options.cholesky = armCholesky;
    const bool factored = arm_.forwardDynamics(qa, va, ta, aa, options);
    if (armMassDiagonal)
        for (int i = 0; i < kArmJointCount; ++i)
            armMassDiagonal[i] = diagonal[i];
    for (int i = 0; i < kArmJointCount; ++i)
        a[i + 1] = aa[i];
    return factored;
}

void PipeRobotMechanics::rigidStep(const JointVector& tau, double h) {
    // This step's acceleration goes straight into the ring's free slot (no copy of the factor).
    const int slot = (historyHead_ + 1) % kRing;
    PastStep& now = history_[static_cast<size_t>(slot)];
    double mass[kArmJointCount] = {};
    // A singular M (a joint without inertia) leaves the arm's q'' = 0 and an unfinished factor:
    // such a step never enters the history.
    const bool factored = acceleration(q_, v_, tau, now.a, mass, &now.cholesky);
    now.tau = tau;
    if (factored && integrator_ == RigidIntegrator::AdamsNystrom4 && historySize_ == kHistory)
        adamsNystromStep(tau, h, now.a);
    else
        rungeKuttaStep(tau, h, now.a);
    historyHead_ = slot;
    historySize_ = factored ? std::min(historySize_ + 1, kHistory) : 0;
    applyCoulomb(h, mass);
}

void PipeRobotMechanics::rungeKuttaStep(const JointVector& tau, double h, const JointVector& a0) {
    // Classical RK4 on (q, v) with tau held.
    JointVector k2v, k3v, k4v, k2a, k3a, k4a;
    const JointVector& k1v = v_;
    const JointVector& k1a = a0;
    k2v = v_ + 0.5 * h * k1a;
    acceleration(q_ + 0.5 * h * k1v, k2v, tau, k2a, nullptr, nullptr);
    k3v = v_ + 0.5 * h * k2a;
    acceleration(q_ + 0.5 * h * k2v, k3v, tau, k3a, nullptr, nullptr);
    k4v = v_ + h * k3a;
    acceleration(q_ + h * k3v, k4v, tau, k4a, nullptr, nullptr);
    q_ += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    v_ += h / 6 * (k1a + 2 * k2a + 2 * k3a + k4a);
}

void PipeRobotMechanics::addPastAcceleration(int back, const JointVector& tau, double weightV,
                                             double weightQ, JointVector& sumV,
                                             JointVector& sumQ) const {
    const PastStep& p = history_[static_cast<size_t>((historyHead_ - back + 1 + kRing) % kRing)];
    // a_j brought to the torque tau: a_j + M_j^-1 (tau - tau_j).
    JointVector a = p.a;
    if (!held_[0]) a[0] += (tau[0] - p.tau[0]) / chuckInertia_;
    Vec dtau = Vec::Zero();
    bool changed = false;
    for (int i = 0; i < kArmJointCount; ++i)
        if (!held_[static_cast<size_t>(i + 1)] && tau[i + 1] != p.tau[i + 1]) {
            dtau[i] = tau[i + 1] - p.tau[i + 1];
            changed = true;
        }
    if (changed) {
        Vec da;
        arm_.solveFactored(p.cholesky, dtau, da);
        for (int i = 0; i < kArmJointCount; ++i)
            a[i + 1] += da[i];
    }
    sumV += weightV * a;
    sumQ += weightQ * a;
}

void PipeRobotMechanics::adamsNystromStep(const JointVector& tau, double h, const JointVector& a0) {
    // Explicit 4-step Adams for v' = a and its Nystrom form for q'' = a: the integrals over the
    // step of the cubic through a_k .. a_k-3, weights 55 -59 37 -9 / 24 for v and, with the
    // kernel (1 - s) for q, 323 -264 159 -38 / 360.
    JointVector sumV = 55 * a0, sumQ = 323 * a0;
    addPastAcceleration(1, tau, -59, -264, sumV, sumQ);
    addPastAcceleration(2, tau, 37, 159, sumV, sumQ);
    addPastAcceleration(3, tau, -9, -38, sumV, sumQ);
    q_ += h * v_ + (h * h / 360) * sumQ;
    v_ += (h / 24) * sumV;
}

void PipeRobotMechanics::applyCoulomb(double h, const double* armMassDiagonal) {
    // Coulomb friction as an impulse over the step: it can stop a joint, never reverse it.
    for (int i = 0; i < kAxisCount; ++i) {
        const auto s = static_cast<size_t>(i);
        if (held_[s]) {
            v_[i] = 0;
            continue;
        }
        const double inertia = i == 0 ? chuckInertia_ : armMassDiagonal[i - 1];
        if (coulomb_[s] <= 0 || inertia <= 0) continue;
        const double budget = coulomb_[s] * h / inertia;
        const double dv = -std::copysign(std::min(std::fabs(v_[i]), budget), v_[i]);
        v_[i] += dv;
        q_[i] += 0.5 * h * dv;
    }
}

void PipeRobotMechanics::step(const JointVector& torque, JointVector& applied) {
    applied.setZero();
    if (model_ == PlantModel::Linear) {
        for (int i = 0; i < kAxisCount; ++i) {
            auto& p = linear_[static_cast<size_t>(i)];
            applied[i] = p.step(torque[i]);
            q_[i] = p.position();
            v_[i] = p.velocity();
        }
        return;
    }
    for (int i = 0; i < kAxisCount; ++i) {
        const double lim = limit_[static_cast<size_t>(i)];
        applied[i] = std::clamp(torque[i], -lim, lim);
    }
    const double h = period_ / substeps_;
    for (int k = 0; k < substeps_; ++k)
        rigidStep(applied, h);
}

void PipeRobotMechanics::gravityTorques(const JointVector& q, JointVector& tau) const {
    tau.setZero();
    if (model_ != PlantModel::RigidBody) return;
    Vec qa = Vec::Zero(), g;
    for (int i = 0; i < kArmJointCount; ++i)
        qa[i] = q[i + 1];
    arm_.gravityTorques(qa, g);
    for (int i = 0; i < kArmJointCount; ++i)
        tau[i + 1] = g[i];
}

double PipeRobotMechanics::holdingTorque(int axis) const {
    JointVector g;
    gravityTorques(q_, g);
    return g[axis];
}

double PipeRobotMechanics::energy() const {
    Vec qa = Vec::Zero(), va = Vec::Zero();
    for (int i = 0; i < kArmJointCount; ++i) {
        qa[i] = q_[i + 1];
        va[i] = v_[i + 1];
    }
    return 0.5 * chuckInertia_ * v_[0] * v_[0] + arm_.kineticEnergy(qa, va) +
           arm_.potentialEnergy(qa);
}

} // namespace cutcell
