// The rigid-body dynamics of a DH chain (core/dynamics/chain_dynamics.h) and the pipe robot's
// plant built on them (core/machines/pipe_robot/pipe_robot_mechanics.h), checked against Orocos
// KDL (Debian's liborocos-kdl-dev, this test's only user), against their own identities (M from
// the inverse dynamics, forward after inverse, energy without friction), against a hand
// calculation of the home pose's gravity torques, and against the linear plant they replace.
#include "core/control/joint_plant.h"
#include "core/control/pid_filter.h"
#include "core/dynamics/chain_dynamics.h"
#include "core/job/default_job.h"
#include "core/machines/pipe_robot/arm_construction.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/machines/pipe_robot/cut_simulation.h"
#include "core/machines/pipe_robot/pipe_robot_mechanics.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>
#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace cutcell {
namespace {

using Vector = ChainDynamics::Vector;
using Matrix = ChainDynamics::Matrix;

constexpr double kTol = 1e-9;

// |a - b| / max(1, |b|) over the first n entries (Euclidean norms).
double relativeError(const Vector& a, const Vector& b, int n) {
    return (a.head(n) - b.head(n)).norm() / std::max(1.0, b.head(n).norm());
}

// The KDL chain of the same DH rows: joint i turns about the segment root's Z (KDL's RotZ
// joint rotates before the segment's tip frame), then Frame::DH(a, alpha, d, theta) =
// Rz(theta) Tz(d) Tx(a) Rx(alpha) with the offset as theta, so the tip is at
// Rz(q + offset) Tz(d) Tx(a) Rx(alpha) - our A_i. KDL's segment inertia is in the tip frame
// (DH frame i) with the rotational inertia about the centre of mass (rigidbodyinertia.hpp:
// "the rotational inertia in the cog"), as LinkInertia holds it. The joint's own inertia
// (KDL's Joint inertia parameter, added by ChainIdSolver_RNE as inertia * qdd and by
// ChainDynParam::JntToMass to H's diagonal) carries our rotor inertia when `withRotors`.
KDL::Chain kdlChain(const ChainDynamics& dyn, bool withRotors) {
    KDL::Chain chain;
    for (int i = 0; i < dyn.size(); ++i) {
        const ChainJoint& j = dyn.joint(i);
        const LinkInertia& l = dyn.link(i);
        const Mat3& I = l.inertia_kg_m2;
        const KDL::Joint joint(KDL::Joint::RotZ, 1.0, 0.0,
                               withRotors ? j.rotor_inertia_kg_m2 : 0.0);
        chain.addSegment(KDL::Segment(
            joint, KDL::Frame::DH(j.a_m, j.alpha_rad, j.d_m, j.theta_offset_rad),
            KDL::RigidBodyInertia(
                l.mass_kg, KDL::Vector(l.com_m.x(), l.com_m.y(), l.com_m.z()),
                KDL::RotationalInertia(I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)))));
    }
    return chain;
}

ChainDynamics withoutRotors(const ChainDynamics& dyn) {
    std::vector<ChainJoint> joints;
    std::vector<LinkInertia> links;
    for (int i = 0; i < dyn.size(); ++i) {
        joints.push_back(dyn.joint(i));
        joints.back().rotor_inertia_kg_m2 = 0;
        links.push_back(dyn.link(i));
    }
    return ChainDynamics(joints, links, dyn.gravity());
}

// A random physical rigid body: principal moments meeting the triangle inequality, turned by a
// random rotation; the centre of mass anywhere within 0.3 m of the frame's origin.
LinkInertia randomLink(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    LinkInertia l;
    l.mass_kg = 0.2 + 5 * u(rng);
    l.com_m = Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5) * 0.6;
    const double a = 0.001 + 0.05 * u(rng), b = 0.001 + 0.05 * u(rng);
    const double c = std::fabs(a - b) + (a + b - std::fabs(a - b)) * u(rng); // |a-b| .. a+b
    const Eigen::Quaterniond r =
        Eigen::Quaterniond(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized();
    const Mat3 R = r.toRotationMatrix();
    l.inertia_kg_m2 = R * Vec3(a, b, c).asDiagonal() * R.transpose();
    return l;
}

ChainDynamics randomChain(std::mt19937& rng, int n) {
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<ChainJoint> joints(static_cast<size_t>(n));
    std::vector<LinkInertia> links;
    for (auto& j : joints) {
        j.alpha_rad = kPi * u(rng);
        j.a_m = 0.5 * u(rng);
        j.d_m = 0.5 * u(rng);
        j.theta_offset_rad = kPi * u(rng);
        j.rotor_inertia_kg_m2 = 0.05 * (1 + u(rng));
        links.push_back(randomLink(rng));
    }
    // Gravity in some direction of the base frame, 9.81 m/s^2.
    const Vec3 g = Vec3(u(rng), u(rng), u(rng)).normalized() * 9.81;
    return ChainDynamics(joints, links, g);
}

Vector randomVector(std::mt19937& rng, int n, double scale) {
    std::uniform_real_distribution<double> u(-scale, scale);
    Vector v = Vector::Zero();
    for (int i = 0; i < n; ++i)
        v[i] = u(rng);
    return v;
}

// KDL's inverse dynamics of the state (no external wrenches).
Vector kdlInverseDynamics(const KDL::Chain& chain, const Vec3& g, const Vector& q, const Vector& qd,
                          const Vector& qdd) {
    const unsigned n = chain.getNrOfJoints();
    KDL::ChainIdSolver_RNE solver(chain, KDL::Vector(g.x(), g.y(), g.z()));
    KDL::JntArray kq(n), kqd(n), kqdd(n), tau(n);
    for (unsigned i = 0; i < n; ++i) {
        kq(i) = q[i];
        kqd(i) = qd[i];
        kqdd(i) = qdd[i];
    }
    const KDL::Wrenches none(chain.getNrOfSegments(), KDL::Wrench::Zero());
    EXPECT_GE(solver.CartToJnt(kq, kqd, kqdd, none, tau), 0);
    Vector out = Vector::Zero();
    for (unsigned i = 0; i < n; ++i)
        out[i] = tau(i);
    return out;
}

Matrix kdlMassMatrix(const KDL::Chain& chain, const Vec3& g, const Vector& q) {
    const unsigned n = chain.getNrOfJoints();
    KDL::ChainDynParam param(chain, KDL::Vector(g.x(), g.y(), g.z()));
    KDL::JntArray kq(n);
    for (unsigned i = 0; i < n; ++i)
        kq(i) = q[i];
    KDL::JntSpaceInertiaMatrix H(n);
    EXPECT_GE(param.JntToMass(kq, H), 0);
    Matrix out = Matrix::Zero();
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j)
            out(i, j) = H(i, j);
    return out;
}

ChainDynamics defaultArm() {
    return pipeRobotArmDynamics(PipeRobotSpec{});
}

// ---------------------------------------------------------------------------------------------
// a. Inverse dynamics == KDL's ChainIdSolver_RNE.

// 1000 random chains (1..6 joints, random DH rows, link inertias, gravity) and states, rotor
// inertia on both sides (KDL's Joint inertia), plus the same without rotors.
TEST(ChainDynamics, InverseDynamicsMatchesKdlOnRandomChains) {
    std::mt19937 rng(2026);
    double worst = 0, worstNoRotor = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        const int n = 1 + trial % kMaxChainJoints;
        const ChainDynamics dyn = randomChain(rng, n);
        const Vector q = randomVector(rng, n, kPi), qd = randomVector(rng, n, 3),
                     qdd = randomVector(rng, n, 10);
        Vector tau;
        dyn.inverseDynamics(q, qd, qdd, tau);
        const Vector ref = kdlInverseDynamics(kdlChain(dyn, true), dyn.gravity(), q, qd, qdd);
        const double e = relativeError(tau, ref, n);
        worst = std::max(worst, e);
        ASSERT_LE(e, kTol) << "trial " << trial << "\nours " << tau.head(n).transpose() << "\nKDL  "
                           << ref.head(n).transpose();

        const ChainDynamics bare = withoutRotors(dyn);
        bare.inverseDynamics(q, qd, qdd, tau);
        const Vector ref0 = kdlInverseDynamics(kdlChain(bare, false), dyn.gravity(), q, qd, qdd);
        worstNoRotor = std::max(worstNoRotor, relativeError(tau, ref0, n));
        ASSERT_LE(relativeError(tau, ref0, n), kTol) << "trial " << trial;
    }
    std::printf("inverse dynamics vs KDL, 1000 random chains: worst relative error %.3g "
                "(rotors), %.3g (none)\n",
                worst, worstNoRotor);
}

// The pipe robot's default arm (pipeRobotArmDynamics(PipeRobotSpec{})) at 1000 random states.
TEST(ChainDynamics, InverseDynamicsMatchesKdlOnTheDefaultArm) {
    const ChainDynamics dyn = defaultArm();
    ASSERT_EQ(dyn.size(), kArmJointCount);
    const KDL::Chain chain = kdlChain(dyn, true);
    std::mt19937 rng(5);
    double worst = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        const Vector q = randomVector(rng, 5, kPi), qd = randomVector(rng, 5, 3),
                     qdd = randomVector(rng, 5, 20);
        Vector tau;
        dyn.inverseDynamics(q, qd, qdd, tau);
        const Vector ref = kdlInverseDynamics(chain, dyn.gravity(), q, qd, qdd);
        worst = std::max(worst, relativeError(tau, ref, 5));
        ASSERT_LE(relativeError(tau, ref, 5), kTol) << "trial " << trial;
    }
    std::printf("inverse dynamics vs KDL, default arm: worst relative error %.3g\n", worst);
}

// ---------------------------------------------------------------------------------------------
// b. The mass matrix and the forward dynamics.

TEST(ChainDynamics, MassMatrixIsSymmetricPositiveDefiniteAndTheInverseDynamicsColumns) {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 1000; ++trial) {
        const int n = 1 + trial % kMaxChainJoints;
        const ChainDynamics dyn = trial % 7 == 0 ? defaultArm() : randomChain(rng, n);
        const int m = dyn.size();
        const Vector q = randomVector(rng, m, kPi);
        Matrix M;
        dyn.massMatrix(q, M);
        const Eigen::MatrixXd Mn = M.topLeftCorner(m, m);
        ASSERT_EQ(Mn, Mn.transpose()) << "trial " << trial; // filled symmetric by construction
        ASSERT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Mn).eigenvalues().minCoeff(), 0)
            << "trial " << trial;
        // Entries past size() stay 0.
        for (int i = 0; i < kMaxChainJoints; ++i)
            for (int j = m; j < kMaxChainJoints; ++j)
                ASSERT_TRUE(M(i, j) == 0 && M(j, i) == 0) << "trial " << trial;
        // Column j = ID(q, 0, e_j) - ID(q, 0, 0), gravity on.
        Vector g0;
        dyn.inverseDynamics(q, Vector::Zero(), Vector::Zero(), g0);
        for (int j = 0; j < m; ++j) {
            Vector e = Vector::Zero(), tau;
            e[j] = 1;
            dyn.inverseDynamics(q, Vector::Zero(), e, tau);
            const Vector col = tau - g0;
            // (Entries past size() are 0 on both sides.)
            const Vector mj = M.col(j);
            ASSERT_LE((col - mj).norm() / std::max(1.0, mj.norm()), kTol)
                << "trial " << trial << " column " << j;
        }
    }
}

TEST(ChainDynamics, ForwardDynamicsInvertsTheInverseDynamics) {
    std::mt19937 rng(12);
    double worst = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        const int n = 1 + trial % kMaxChainJoints;
        const ChainDynamics dyn = trial % 7 == 0 ? defaultArm() : randomChain(rng, n);
        const int m = dyn.size();
        const Vector q = randomVector(rng, m, kPi), qd = randomVector(rng, m, 3),
                     qdd = randomVector(rng, m, 10);
        Vector tau, back;
        dyn.inverseDynamics(q, qd, qdd, tau);
        ASSERT_TRUE(dyn.forwardDynamics(q, qd, tau, back));
        worst = std::max(worst, relativeError(back, qdd, m));
        ASSERT_LE(relativeError(back, qdd, m), kTol) << "trial " << trial;
    }
    std::printf("forward(inverse(qdd)) vs qdd: worst relative error %.3g\n", worst);
}

// Held joints leave the system: their qdd is 0 and the others solve the reduced equations.
TEST(ChainDynamics, ForwardDynamicsWithHeldJoints) {
    std::mt19937 rng(13);
    const ChainDynamics dyn = defaultArm();
    for (int trial = 0; trial < 200; ++trial) {
        const unsigned held = static_cast<unsigned>(trial) % 32u;
        Vector q = randomVector(rng, 5, kPi), qd = randomVector(rng, 5, 3),
               qdd = randomVector(rng, 5, 10);
        for (int i = 0; i < 5; ++i)
            if (held & (1u << i)) qdd[i] = 0;
        Vector tau, back;
        dyn.inverseDynamics(q, qd, qdd, tau);
        // A held joint's torque is anything (the brake takes the rest).
        for (int i = 0; i < 5; ++i)
            if (held & (1u << i)) tau[i] += 100;
        ChainDynamics::ForwardOptions o;
        o.held_mask = held;
        ASSERT_TRUE(dyn.forwardDynamics(q, qd, tau, back, o));
        ASSERT_LE(relativeError(back, qdd, 5), kTol) << "trial " << trial;
    }
}

// KDL's ChainDynParam::JntToMass: without rotors, and with them as KDL's joint inertia.
TEST(ChainDynamics, MassMatrixMatchesKdlChainDynParam) {
    std::mt19937 rng(14);
    double worst = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        const int n = 1 + trial % kMaxChainJoints;
        const ChainDynamics dyn = trial % 7 == 0 ? defaultArm() : randomChain(rng, n);
        const int m = dyn.size();
        const Vector q = randomVector(rng, m, kPi);
        for (const bool rotors : {false, true}) {
            const ChainDynamics d = rotors ? dyn : withoutRotors(dyn);
            Matrix M;
            d.massMatrix(q, M);
            const Matrix H = kdlMassMatrix(kdlChain(d, rotors), d.gravity(), q);
            const double e = (M - H).norm() / std::max(1.0, H.norm());
            worst = std::max(worst, e);
            ASSERT_LE(e, kTol) << "trial " << trial << " rotors " << rotors << "\nours\n"
                               << M.topLeftCorner(m, m) << "\nKDL\n"
                               << H.topLeftCorner(m, m);
        }
    }
    std::printf("mass matrix vs KDL JntToMass: worst relative error %.3g\n", worst);
}

// ---------------------------------------------------------------------------------------------
// c. Energy: without friction and torque the plant's total energy stays put.

class EnergyWithoutFriction : public ::testing::TestWithParam<RigidIntegrator> {};

TEST_P(EnergyWithoutFriction, IsConservedWithoutTorque) {
    Job job = defaultJob();
    PipeRobotSpec& spec = pipeRobotSpec(job);
    ASSERT_EQ(spec.plant_model, PlantModel::RigidBody);
    for (DriveTrainRow& d : spec.drives) {
        d.viscous_nm_s_per_rad = 0;
        d.coulomb_nm = 0;
    }
    const double T = 0.001;
    PipeRobotMechanics plant(job, T, 1, GetParam());
    ASSERT_EQ(plant.integrator(), GetParam());
    JointVector q = JointVector::Zero(), qd = JointVector::Zero();
    q.head(kAxisCount) << 0.3, 0.4, 0.9, -0.6, 0.8, -0.5;
    qd.head(kAxisCount) << 1.0, 0.8, -1.2, 1.5, -2.0, 3.0;
    plant.setState(q, qd);
    const double e0 = plant.energy();
    double maxKinetic = 0, maxDrift = 0;
    const JointVector zero = JointVector::Zero();
    JointVector applied;
    auto kinetic = [&] {
        Vector qa = Vector::Zero(), va = Vector::Zero();
        for (int i = 0; i < kArmJointCount; ++i) {
            qa[i] = plant.position(i + 1);
            va[i] = plant.velocity(i + 1);
        }
        return 0.5 * plant.chuckInertia() * plant.velocity(0) * plant.velocity(0) +
               plant.arm().kineticEnergy(qa, va);
    };
    maxKinetic = kinetic();
    for (int k = 0; k < 10000; ++k) { // 10 s
        plant.step(zero, applied);
        maxKinetic = std::max(maxKinetic, kinetic());
        maxDrift = std::max(maxDrift, std::fabs(plant.energy() - e0));
    }
    std::printf("energy, 10 s at 1 ms without friction (%s): max |E - E0| = %.3g J, max kinetic "
                "%.4g J, relative %.3g\n",
                integratorName(GetParam()), maxDrift, maxKinetic, maxDrift / maxKinetic);
    EXPECT_GT(maxKinetic, 1.0); // the arm does swing
    EXPECT_LE(maxDrift, 1e-6 * maxKinetic);
}

INSTANTIATE_TEST_SUITE_P(PipeRobotMechanics, EnergyWithoutFriction,
                         ::testing::Values(RigidIntegrator::AdamsNystrom4,
                                           RigidIntegrator::RungeKutta4),
                         [](const ::testing::TestParamInfo<RigidIntegrator>& param) {
                             return std::string(param.param == RigidIntegrator::RungeKutta4
                                                    ? "RungeKutta4"
                                                    : "AdamsNystrom4");
                         });

// ---------------------------------------------------------------------------------------------
// d. Gravity at the home pose, by hand.

TEST(PipeRobotMechanics, HomePoseGravityTorquesByHand) {
    // The arm's DH rows (seed Table 1, rows 1..5; alpha, a, d in deg and m):
    //   1: alpha 90, a 0,     d 0.371      2: alpha 0, a 0.157, d 0
    //   3: alpha 0,  a 0.120, d 0          4: alpha 90, a 0.050, d 0
    //   5: alpha 0,  a 0,     d 0.210
    // At q = 0, with A_i = Rz(0) Tz(d) Tx(a) Rx(alpha):
    //   o1 = (0, 0, 0.371), R1 = Rx(90): x1 = x0, y1 = z0, z1 = -y0
    //   o2 = o1 + 0.157 x1 = (0.157, 0, 0.371), R2 = R1   link 2 horizontal along x0
    //   o3 = o2 + 0.120 x1 = (0.277, 0, 0.371), R3 = R1   link 3 horizontal along x0
    //   o4 = o3 + 0.050 x1 = (0.327, 0, 0.371), R4 = R1 Rx(90): x4 = x0, z4 = -z0
    //   o5 = o4 + 0.210 z4 = (0.327, 0, 0.161)            the torch hangs straight down
    // Joints 2, 3, 4 turn about z1 = z2 = z3 = -y0 (horizontal); joint 1 (z0) and joint 5
    // (z4 = -z0) are vertical, so gravity has no torque on them. For gravity (0, 0, -g) a
    // point mass m at c needs, on an axis -y0 through o, the holding torque
    //   tau = -m g_vec . ((-y0) x (c - o)) = m g (c_x - o_x)
    // and every frame's x axis is x0, so a link's centre of mass lies at c_x = o_x + com_x.
    //
    // The default construction (arm_construction.h): link i (i = 2..4) is an aluminium tube
    // (2700 kg/m^3) from frame i-1's origin to frame i's, i.e. along -x_i from o_i over a_i
    // (its centre at com_x = -a_i / 2), plus the actuator of joint i + 1 centred on o_i
    // (com_x = 0); link 5 is the torch rod on z5, com_x = 0.
    const ArmConstruction c;
    const double g = kStandardGravity;
    auto tubeMass = [&](double outerMm, double wallMm, double length) {
        const double ro = 0.5e-3 * outerMm, ri = ro - 1e-3 * wallMm;
        return c.density_kg_m3 * kPi * (ro * ro - ri * ri) * length;
    };
    const double tube2 = tubeMass(50, 3, 0.157), act2 = 1.0; // actuator of joint 3
    const double tube3 = tubeMass(40, 3, 0.120), act3 = 0.6; // actuator of joint 4
    const double tube4 = tubeMass(40, 3, 0.050), act4 = 0.4; // actuator of joint 5
    const double m2 = tube2 + act2, m3 = tube3 + act3, m4 = tube4 + act4, m5 = 0.9;
    const double cx2 = 0.157 + tube2 * (-0.157 / 2) / m2; // o2x + com_x
    const double cx3 = 0.277 + tube3 * (-0.120 / 2) / m3;
    const double cx4 = 0.327 + tube4 * (-0.050 / 2) / m4;
    const double cx5 = 0.327;
    const double tau2 = g * (m2 * cx2 + m3 * cx3 + m4 * cx4 + m5 * cx5);                    // o1x 0
    const double tau3 = g * (m3 * (cx3 - 0.157) + m4 * (cx4 - 0.157) + m5 * (cx5 - 0.157)); // o2x
    const double tau4 = g * (m4 * (cx4 - 0.277) + m5 * (cx5 - 0.277));                      // o3x

    // The construction's link table agrees with the hand figures (mass and com_x).
    const PipeRobotSpec spec;
    const double mHand[5] = {0, m2, m3, m4, m5};
    const double comHand[5] = {0, cx2 - 0.157, cx3 - 0.277, cx4 - 0.327, 0};
    for (int i = 1; i < 5; ++i) {
        EXPECT_NEAR(spec.links[static_cast<size_t>(i)].mass_kg, mHand[i], 1e-12 * mHand[i]);
        EXPECT_NEAR(spec.links[static_cast<size_t>(i)].com_x_mm, 1e3 * comHand[i], 1e-9);
    }

    const ChainDynamics arm = defaultArm();
    Vector tau;
    arm.gravityTorques(Vector::Zero(), tau);
    const double scale = std::max(1.0, std::fabs(tau2));
    std::printf("home pose gravity torques (N m): ours %.9f %.9f %.9f %.9f %.9f, by hand 0 "
                "%.9f %.9f %.9f 0\n",
                tau[0], tau[1], tau[2], tau[3], tau[4], tau2, tau3, tau4);
    EXPECT_NEAR(tau[0], 0, kTol * scale);
    EXPECT_NEAR(tau[1], tau2, kTol * std::max(1.0, std::fabs(tau2)));
    EXPECT_NEAR(tau[2], tau3, kTol * std::max(1.0, std::fabs(tau3)));
    EXPECT_NEAR(tau[3], tau4, kTol * std::max(1.0, std::fabs(tau4)));
    EXPECT_NEAR(tau[4], 0, kTol * scale);
}

// ---------------------------------------------------------------------------------------------
// e. The integrator's error on the default job's cut: 1 RK4 step per period (what simulateCut
// runs) against 32 substeps, each closed by the same PID loop as simulateCut's.

struct ClosedLoopRun {
    std::vector<JointVector> q;              // actual positions at every sample
    std::array<double, kAxisCount> maxErr{}; // max |ref - actual| per axis (rad)
};

// simulateCut's loop (cut_simulation.cpp) with the plant's substeps and integrator as
// parameters.
ClosedLoopRun runClosedLoop(const Job& job, const CutPlan& plan, int substeps,
                            RigidIntegrator integrator) {
    const PipeRobotSpec& spec = pipeRobotSpec(job);
    const double T = job.sim.period_s;
    std::array<PidFilter, kAxisCount> pid;
    PipeRobotMechanics plant(job, T, substeps, integrator);
    plant.setState(plan.spline.evaluate(0).q);
    for (int i = 0; i < kAxisCount; ++i) {
        pid[static_cast<size_t>(i)].configure(spec.controller[static_cast<size_t>(i)], T);
        if (!spec.gravity_feedforward) pid[static_cast<size_t>(i)].preload(plant.holdingTorque(i));
    }
    const double simulated = std::max(job.sim.duration_s, plan.cut_time_s);
    const long steps = static_cast<long>(std::ceil(simulated / T - 1e-9));
    ClosedLoopRun run;
    run.q.reserve(static_cast<size_t>(steps) + 1);
    JointVector torque = JointVector::Zero(), applied, gravity = JointVector::Zero(),
                actual = JointVector::Zero();
    for (long k = 0; k <= steps; ++k) {
        const double t = static_cast<double>(k) * T;
        const JointVector ref = plan.spline.position(t);
        for (int i = 0; i < kAxisCount; ++i)
            actual[i] = plant.position(i);
        run.q.push_back(actual);
        for (int i = 0; i < kAxisCount; ++i)
            run.maxErr[static_cast<size_t>(i)] =
                std::max(run.maxErr[static_cast<size_t>(i)], std::fabs(ref[i] - actual[i]));
        if (spec.gravity_feedforward) plant.gravityTorques(actual, gravity);
        for (int i = 0; i < kAxisCount; ++i)
            torque[i] = pid[static_cast<size_t>(i)].step(ref[i] - actual[i]) + gravity[i];
        plant.step(torque, applied);
    }
    return run;
}

// The largest joint difference (rad, per axis) between two runs sample by sample.
std::array<double, kAxisCount> maxDifference(const ClosedLoopRun& a, const ClosedLoopRun& b) {
    std::array<double, kAxisCount> diff{};
    for (size_t k = 0; k < a.q.size(); ++k)
        for (int i = 0; i < kAxisCount; ++i)
            diff[static_cast<size_t>(i)] =
                std::max(diff[static_cast<size_t>(i)], std::fabs(a.q[k][i] - b.q[k][i]));
    return diff;
}

// Each integrator at one step per period against RK4 at 32 substeps, on the default job (with
// friction) and on its frictionless variant (where the integrators' order shows undisturbed).
struct IntegratorCase {
    RigidIntegrator integrator;
    bool friction;
    double boundDeg; // measured figure x ~1.5 (printed below)
};

class IntegratorError : public ::testing::TestWithParam<IntegratorCase> {};

TEST_P(IntegratorError, OneStepPerPeriodAgainst32Rk4Substeps) {
    const IntegratorCase c = GetParam();
    Job job = defaultJob();
    ASSERT_EQ(pipeRobotSpec(job).plant_model, PlantModel::RigidBody);
    if (!c.friction)
        for (DriveTrainRow& d : pipeRobotSpec(job).drives)
            d.coulomb_nm = 0;
    const CutPlan plan = planCut(job);
    ASSERT_TRUE(plan.reachable) << plan.problem;
    const ClosedLoopRun one = runClosedLoop(job, plan, 1, c.integrator);
    const ClosedLoopRun ref = runClosedLoop(job, plan, 32, RigidIntegrator::RungeKutta4);
    ASSERT_EQ(one.q.size(), ref.q.size());
    const std::array<double, kAxisCount> diff = maxDifference(one, ref);
    const double worst = rad2deg(*std::max_element(diff.begin(), diff.end()));
    std::printf("%s, 1 step per period vs RK4 x 32, default cut %s friction (%zu samples): max "
                "joint difference (deg)",
                integratorName(c.integrator), c.friction ? "with" : "without", one.q.size());
    for (double d : diff)
        std::printf(" %.3g", rad2deg(d));
    std::printf("; worst %.3g deg; tracking error max (deg)", worst);
    for (int i = 0; i < kAxisCount; ++i)
        std::printf(" %.3g", rad2deg(one.maxErr[static_cast<size_t>(i)]));
    std::printf("\n");
    EXPECT_LE(worst, c.boundDeg);
}

INSTANTIATE_TEST_SUITE_P(
    PipeRobotMechanics, IntegratorError,
    // Measured (deg): 2.06e-4, 9.79e-6, 2.42e-13, 5.69e-9. Without friction the differences
    // are the methods' truncation errors; with it they come from the Coulomb impulse applied
    // once per period instead of 32 times (RK4 1 vs 32 differs by 1e-13 without it).
    ::testing::Values(IntegratorCase{RigidIntegrator::RungeKutta4, true, 3e-4},
                      IntegratorCase{RigidIntegrator::AdamsNystrom4, true, 1.5e-5},
                      IntegratorCase{RigidIntegrator::RungeKutta4, false, 4e-13},
                      IntegratorCase{RigidIntegrator::AdamsNystrom4, false, 1e-8}),
    [](const ::testing::TestParamInfo<IntegratorCase>& param) {
        return std::string(param.param.integrator == RigidIntegrator::RungeKutta4
                               ? "RungeKutta4"
                               : "AdamsNystrom4") +
               (param.param.friction ? "WithFriction" : "WithoutFriction");
    });

// simulateCut runs the plant as this test's loop does, with the integrator Auto picks.
TEST(PipeRobotMechanics, SimulateCutRunsTheAutoIntegrator) {
    const Job job = defaultJob();
    const CutPlan plan = planCut(job);
    ASSERT_TRUE(plan.reachable) << plan.problem;
    const double T = job.sim.period_s;
    EXPECT_EQ(PipeRobotMechanics(job, T).integrator(), RigidIntegrator::AdamsNystrom4);
    const ClosedLoopRun run = runClosedLoop(job, plan, 1, RigidIntegrator::Auto);
    const TrackingReport report = simulateCut(job, plan);
    for (int i = 0; i < kAxisCount; ++i)
        EXPECT_NEAR(rad2deg(run.maxErr[static_cast<size_t>(i)]), report.maxAbs(i),
                    1e-12 + 1e-9 * report.maxAbs(i))
            << "axis " << i;
}

// A joint without any inertia (the job allows zero mass, tensor and rotor) makes M singular: the
// forward dynamics refuses (the arm's q'' = 0) and the multistep method must not use the
// unfinished factor of such a step: the plant then runs as RK4 does, bit for bit.
TEST(PipeRobotMechanics, ASingularMassMatrixNeverEntersTheHistory) {
    Job job = defaultJob();
    PipeRobotSpec& spec = pipeRobotSpec(job);
    spec.links[4] = ArmLinkRow{}; // the torch link: no mass, no inertia
    spec.drives[5].rotor_inertia_g_cm2 = 0;
    for (DriveTrainRow& d : spec.drives)
        d.viscous_nm_s_per_rad = 0; // Auto then takes the multistep method
    PipeRobotMechanics plant(job, 0.001), rk4(job, 0.001, 1, RigidIntegrator::RungeKutta4);
    ASSERT_EQ(plant.integrator(), RigidIntegrator::AdamsNystrom4);
    JointVector q = JointVector::Zero();
    q.head(kAxisCount) << 0.1, 0.3, 0.5, -0.4, 0.6, 0.2;
    plant.setState(q);
    rk4.setState(q);
    JointVector torque = JointVector::Zero(), applied;
    for (int k = 0; k < 50; ++k) {
        for (int i = 0; i < kAxisCount; ++i)
            torque[i] = std::sin(0.1 * k + i);
        plant.step(torque, applied);
        rk4.step(torque, applied);
        for (int i = 0; i < kAxisCount; ++i) {
            ASSERT_TRUE(std::isfinite(plant.position(i))) << "step " << k << " axis " << i;
            ASSERT_EQ(plant.position(i), rk4.position(i)) << "step " << k << " axis " << i;
            ASSERT_EQ(plant.velocity(i), rk4.velocity(i)) << "step " << k << " axis " << i;
        }
    }
}

// Auto falls back to RK4 where viscous friction is too stiff for the multistep method.
TEST(PipeRobotMechanics, AutoTakesRk4ForStiffViscousFriction) {
    Job job = defaultJob();
    const double T = job.sim.period_s;
    DriveTrainRow& wrist = pipeRobotSpec(job).drives[5];
    const double J = wrist.gear_ratio * wrist.gear_ratio * wrist.rotor_inertia_g_cm2 * 1e-7;
    wrist.viscous_nm_s_per_rad = 0.09 * J / T; // h b / J = 0.09: inside the margin
    EXPECT_EQ(PipeRobotMechanics(job, T).integrator(), RigidIntegrator::AdamsNystrom4);
    wrist.viscous_nm_s_per_rad = 0.11 * J / T;
    EXPECT_EQ(PipeRobotMechanics(job, T).integrator(), RigidIntegrator::RungeKutta4);
    // Why: beyond its stability interval (h b / J = 0.3 for a lone joint) the multistep method
    // amplifies a decaying motion; RK4 (stable to 2.78) damps it. The wrist alone moves, the
    // other joints are braked.
    wrist.viscous_nm_s_per_rad = 0.6 * J / T;
    for (DriveTrainRow& d : pipeRobotSpec(job).drives)
        d.coulomb_nm = 0;
    auto finalSpeed = [&](RigidIntegrator integrator) {
        PipeRobotMechanics plant(job, T, 1, integrator);
        for (int i = 0; i < kAxisCount - 1; ++i)
            plant.setHeld(i, true);
        JointVector v = JointVector::Zero();
        v[kAxisCount - 1] = 1.0;
        plant.setState(JointVector::Zero(), v);
        JointVector applied;
        for (int k = 0; k < 200; ++k)
            plant.step(JointVector::Zero(), applied);
        return std::fabs(plant.velocity(kAxisCount - 1));
    };
    const double multistep = finalSpeed(RigidIntegrator::AdamsNystrom4);
    const double rungeKutta = finalSpeed(RigidIntegrator::RungeKutta4);
    std::printf("wrist at h b / J = 0.6 (above the link's own inertia), |v| after 0.2 s from 1 "
                "rad/s: Adams-Nystrom %.3g, RK4 %.3g\n",
                multistep, rungeKutta);
    EXPECT_GT(multistep, 1.0);
    EXPECT_LT(rungeKutta, 1.0);
}

// ---------------------------------------------------------------------------------------------
// f. The linear mode is six JointPlants, bit for bit.

TEST(PipeRobotMechanics, LinearModeIsSixJointPlantsBitForBit) {
    Job job = defaultJob();
    pipeRobotSpec(job).plant_model = PlantModel::Linear;
    const PipeRobotSpec& spec = pipeRobotSpec(job);
    const double T = job.sim.period_s;
    PipeRobotMechanics plant(job, T);
    ASSERT_EQ(plant.model(), PlantModel::Linear);
    std::array<JointPlant, kAxisCount> ref;
    std::mt19937 rng(21);
    JointVector q0 = JointVector::Zero(), v0 = JointVector::Zero();
    for (int i = 0; i < kAxisCount; ++i) {
        q0[i] = std::uniform_real_distribution<double>(-1, 1)(rng);
        v0[i] = std::uniform_real_distribution<double>(-1, 1)(rng);
        ref[static_cast<size_t>(i)].configure(spec.plant[static_cast<size_t>(i)], T);
        ref[static_cast<size_t>(i)].setState(q0[i], v0[i]);
        EXPECT_EQ(plant.torqueLimit(i), ref[static_cast<size_t>(i)].torqueLimit());
    }
    plant.setState(q0, v0);
    JointVector torque = JointVector::Zero(), applied;
    for (int k = 0; k < 20000; ++k) {
        for (int i = 0; i < kAxisCount; ++i) {
            // Up to 1.5 x the limit: the clamp is part of the plant.
            const double lim = ref[static_cast<size_t>(i)].torqueLimit();
            torque[i] = std::uniform_real_distribution<double>(-1.5 * lim, 1.5 * lim)(rng);
        }
        plant.step(torque, applied);
        for (int i = 0; i < kAxisCount; ++i) {
            JointPlant& p = ref[static_cast<size_t>(i)];
            const double a = p.step(torque[i]);
            ASSERT_EQ(applied[i], a) << "step " << k << " axis " << i;
            ASSERT_EQ(plant.position(i), p.position()) << "step " << k << " axis " << i;
            ASSERT_EQ(plant.velocity(i), p.velocity()) << "step " << k << " axis " << i;
        }
    }
}

} // namespace
} // namespace cutcell
