// The discretised PID with first-order filter matches the continuous one (seed Eq. 69-79),
// integrated independently with a fine RK4, and the plant model matches its ODE.
#include "core/control/joint_plant.h"
#include "core/control/pid_filter.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace cutcell;

namespace {

// Continuous controller state-space, Eq. (73)-(74), integrated by RK4 with a constant error.
struct ContinuousPid {
    PidGains g;
    double x1 = 0, x2 = 0;
    double output(double e) const {
        return (g.kp / g.tau_f - g.kd / (g.tau_f * g.tau_f)) * x1 + g.ki / g.tau_f * x2 +
               g.kd / g.tau_f * e;
    }
    void advance(double e, double T, int substeps) {
        const double h = T / substeps;
        for (int i = 0; i < substeps; ++i) {
            auto f = [&](double a1, double) { return std::pair{-a1 / g.tau_f + e, a1}; };
            auto [k1a, k1b] = f(x1, x2);
            auto [k2a, k2b] = f(x1 + h / 2 * k1a, x2 + h / 2 * k1b);
            auto [k3a, k3b] = f(x1 + h / 2 * k2a, x2 + h / 2 * k2b);
            auto [k4a, k4b] = f(x1 + h * k3a, x2 + h * k3b);
            x1 += h / 6 * (k1a + 2 * k2a + 2 * k3a + k4a);
            x2 += h / 6 * (k1b + 2 * k2b + 2 * k3b + k4b);
        }
    }
};

} // namespace

TEST(Pid, DiscreteStepResponseMatchesTheContinuousController) {
    const PidGains gains[] = {
        {3240, 64800, 53, 0.002}, {10, 2, 0.5, 0.05}, {1, 0, 0, 0.01}, {0, 5, 0, 0.001}};
    for (const PidGains& g : gains) {
        const double T = 0.001;
        PidFilter pid(g, T);
        ContinuousPid ref{g};
        double worst = 0, scale = 1;
        for (int k = 0; k < 200; ++k) {
            const double e = 1.0; // unit step
            const double vd = pid.step(e);
            const double vc = ref.output(e);
            worst = std::max(worst, std::fabs(vd - vc));
            scale = std::max(scale, std::fabs(vc));
            ref.advance(e, T, 200);
        }
        EXPECT_LE(worst / scale, 1e-9) << "kp " << g.kp << " tau " << g.tau_f;
    }
}

TEST(Pid, StepResponseHasTheAnalyticForm) {
    // Inverse Laplace of C(s)/s: V(t) = Ki t + (Kp - Ki tau) (1 - e^{-t/tau}) + (Kd/tau)
    // e^{-t/tau}.
    const PidGains g{12, 30, 0.4, 0.02};
    PidFilter pid(g, 0.001);
    for (int k = 0; k < 500; ++k) {
        const double t = 0.001 * k;
        const double expected = g.ki * t + (g.kp - g.ki * g.tau_f) * (1 - std::exp(-t / g.tau_f)) +
                                g.kd / g.tau_f * std::exp(-t / g.tau_f);
        EXPECT_NEAR(pid.step(1.0), expected, 1e-9 * (1 + std::fabs(expected))) << "t = " << t;
    }
}

TEST(Plant, ExactStepMatchesTheOde) {
    const JointPlantParams p{0.3, 1.2, 50};
    JointPlant plant(p, 0.001);
    plant.setState(0.2, -0.5);
    double q = 0.2, v = -0.5;
    const double u = 3.0;
    for (int k = 0; k < 1000; ++k) {
        plant.step(u);
        const double h = 0.001 / 100;
        for (int i = 0; i < 100; ++i) { // RK4 on q' = v, v' = (u - b v) / J
            auto acc = [&](double vv) {
                return (u - p.viscous_nm_s_per_rad * vv) / p.inertia_kg_m2;
            };
            const double k1v = acc(v), k1q = v;
            const double k2v = acc(v + h / 2 * k1v), k2q = v + h / 2 * k1v;
            const double k3v = acc(v + h / 2 * k2v), k3q = v + h / 2 * k2v;
            const double k4v = acc(v + h * k3v), k4q = v + h * k3v;
            q += h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
            v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        }
    }
    EXPECT_NEAR(plant.position(), q, 1e-9);
    EXPECT_NEAR(plant.velocity(), v, 1e-9);
}

TEST(Plant, TorqueIsLimited) {
    JointPlant plant({0.1, 0, 2.0}, 0.001);
    EXPECT_EQ(plant.step(100), 2.0);
    EXPECT_EQ(plant.step(-100), -2.0);
    EXPECT_NEAR(plant.velocity(), 0, 1e-12);
}

TEST(Pid, ClosedLoopSettlesOnAStepWithoutSteadyError) {
    const PidGains g{3240, 64800, 53, 0.002};
    PidFilter pid(g, 0.001);
    JointPlant plant({0.3, 1.0, 1e6}, 0.001);
    for (int k = 0; k < 3000; ++k)
        plant.step(pid.step(0.01 - plant.position()));
    EXPECT_NEAR(plant.position(), 0.01, 1e-7);
}
