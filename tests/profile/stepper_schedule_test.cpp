// Stepper output: pulse counts per step and the constant-surface-speed pulse-rate schedule.
#include "core/machines/profile_cutter/profile_cutter_spec.h"
#include "core/machines/profile_cutter/stepper_schedule.h"
#include "profile_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cutcell {
namespace {

std::vector<Job> jobs() {
    std::vector<Job> out{test::exampleProfileJob()};
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> U(0, 1);
    for (int k = 0; k < 30; ++k) {
        Job j = test::randomProfileJob(rng, k % 2 ? CutTarget::Main : CutTarget::Branch);
        cutcell::profileCutterSpec(j).steps_per_rev_a = 100 + static_cast<int>(U(rng) * 900);
        cutcell::profileCutterSpec(j).pulses_per_step_a = 1 + static_cast<int>(U(rng) * 32);
        cutcell::profileCutterSpec(j).mm_per_pulse_x = 0.001 + 0.02 * U(rng);
        j.cut.speed_mm_s = 2 + 20 * U(rng);
        out.push_back(j);
    }
    return out;
}

// Every prefix of pulses sums to the travel to that point (rounded once, never accumulated);
// over the closed cut X returns to its start and A makes one turn (branch) or returns (hole).
TEST(StepperSchedule, PulseCountsSumToTheTravel) {
    for (const Job& job : jobs()) {
        const ProfileCut cut = computeProfileCut(job);
        const PulseSchedule s =
            buildPulseSchedule(cut, cutcell::profileCutterSpec(job), job.cut.speed_mm_s);
        ASSERT_EQ(s.steps.size(), cut.points.size());
        std::int64_t px = s.x_start_pulses, pa = s.a_start_pulses;
        for (size_t i = 0; i < s.steps.size(); ++i) {
            px += s.steps[i].x_pulses;
            pa += s.steps[i].a_pulses;
            const ProfilePoint target = cut.closedAt(i + 1);
            EXPECT_LE(std::fabs(static_cast<double>(px) * s.mm_per_pulse_x - target.x_mm),
                      s.mm_per_pulse_x / 2 + 1e-9);
            EXPECT_LE(std::fabs(static_cast<double>(pa) * s.deg_per_pulse_a - target.a_deg),
                      s.deg_per_pulse_a / 2 + 1e-9);
        }
        EXPECT_EQ(px, s.x_start_pulses);
        const std::int64_t turn =
            static_cast<std::int64_t>(cutcell::profileCutterSpec(job).steps_per_rev_a) *
            cutcell::profileCutterSpec(job).pulses_per_step_a;
        EXPECT_EQ(pa - s.a_start_pulses, job.cut.target == CutTarget::Branch ? turn : 0);
        // On the branch end every step turns the pipe by exactly pulses_per_step_a (the seed's
        // grid).
        if (job.cut.target == CutTarget::Branch) {
            for (const auto& st : s.steps)
                EXPECT_EQ(st.a_pulses, cutcell::profileCutterSpec(job).pulses_per_step_a);
        }
    }
}

// The seed's constant cutting rate: on every step the torch covers the surface distance of the
// pulses it sends at the cutting speed, and each axis's rate delivers its count in that time.
TEST(StepperSchedule, SurfaceSpeedIsConstant) {
    for (const Job& job : jobs()) {
        const ProfileCut cut = computeProfileCut(job);
        const PulseSchedule s =
            buildPulseSchedule(cut, cutcell::profileCutterSpec(job), job.cut.speed_mm_s);
        const double radPerPulse = deg2rad(s.deg_per_pulse_a);
        double total = 0;
        for (const auto& st : s.steps) {
            const double dx = static_cast<double>(st.x_pulses) * s.mm_per_pulse_x;
            const double da = static_cast<double>(st.a_pulses) * radPerPulse;
            const double ds = std::hypot(dx, cut.work_radius_mm * da);
            total += st.dt_s;
            if (ds == 0) {
                EXPECT_EQ(st.dt_s, 0);
                continue;
            }
            EXPECT_NEAR(ds / st.dt_s, job.cut.speed_mm_s, 1e-9 * job.cut.speed_mm_s);
            EXPECT_NEAR(st.x_rate_hz * st.dt_s, std::fabs(static_cast<double>(st.x_pulses)), 1e-6);
            EXPECT_NEAR(st.a_rate_hz * st.dt_s, std::fabs(static_cast<double>(st.a_pulses)), 1e-6);
        }
        EXPECT_NEAR(total, s.total_time_s, 1e-9 * total);
        EXPECT_NEAR(s.total_time_s * job.cut.speed_mm_s, s.developed_length_mm,
                    1e-9 * s.developed_length_mm);
        // The quantised path is the developed cut within the pulse resolution.
        const double ideal = cut.developedLength();
        EXPECT_NEAR(s.developed_length_mm, ideal, 0.01 * ideal) << job.name;
    }
}

TEST(StepperSchedule, RateAboveTheCardLimitIsReported) {
    Job job = test::exampleProfileJob();
    cutcell::profileCutterSpec(job).max_pulse_rate_hz = 500;
    const PulseSchedule s = buildPulseSchedule(computeProfileCut(job),
                                               cutcell::profileCutterSpec(job), job.cut.speed_mm_s);
    ASSERT_FALSE(s.problem.empty());
    EXPECT_NE(s.problem.find("profile_cutter.max_pulse_rate_hz = 500 Hz"), std::string::npos)
        << s.problem;
    EXPECT_GT(std::max(s.max_x_rate_hz, s.max_a_rate_hz), 500);
    cutcell::profileCutterSpec(job).max_pulse_rate_hz = 200000;
    EXPECT_TRUE(buildPulseSchedule(computeProfileCut(job), cutcell::profileCutterSpec(job),
                                   job.cut.speed_mm_s)
                    .problem.empty());
}

} // namespace
} // namespace cutcell
