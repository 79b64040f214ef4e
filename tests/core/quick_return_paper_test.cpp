// Seed 004's experiment 1 with the paper's own masses and gains (paper_parameters.h): the
// limit-cycle detector on synthetic signals (property test), the shipped job against the
// seed's printed figures, and the study of experiment 1 running to finite figures. No figure
// measured on the simulation is an expectation here: the README states them.
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/machines/quick_return/paper_parameters.h"
#include "core/machines/quick_return/quick_return_module.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace cutcell::quick_return {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kDt = 0.001; // s, the experiments' sample time

std::string shippedJob(const char* name) {
    std::string path = CUTCELL_SOURCE_DIR;
    path += "/resources/jobs/";
    path += name;
    return path;
}

// A forced response like experiment 1's: the 0.5 Hz reference with harmonics and a 3 Hz
// disturbance, plus white noise; `extra` adds the oscillation under test at t.
template <class Extra>
std::vector<double> forcedSignal(std::mt19937& rng, double seconds, double noise, Extra extra) {
    std::uniform_real_distribution<double> u(-1, 1);
    std::normal_distribution<double> g(0, noise);
    const double a1 = u(rng), a2 = 0.3 * u(rng), a3 = 0.1 * u(rng), ad = 0.2 * u(rng);
    const double p1 = 3 * u(rng), p2 = 3 * u(rng), p3 = 3 * u(rng), pd = 3 * u(rng);
    const double offset = u(rng);
    std::vector<double> x(static_cast<size_t>(std::llround(seconds / kDt)));
    for (size_t i = 0; i < x.size(); ++i) {
        const double t = static_cast<double>(i) * kDt;
        x[i] = offset + a1 * std::sin(kTwoPi * 0.5 * t + p1) +
               a2 * std::sin(kTwoPi * 1.0 * t + p2) + a3 * std::sin(kTwoPi * 1.5 * t + p3) +
               ad * std::sin(kTwoPi * 3 * t + pd) + g(rng) + extra(t);
    }
    return x;
}

LimitCycleOptions experimentOneLike() {
    LimitCycleOptions o;
    o.window_s = 4;
    o.forced_hz = {0.5, 3};
    return o;
}

// A frequency in [lo, hi] Hz at least 0.2 Hz from every forced line (0.5 Hz comb up to 10 Hz,
// 3 Hz comb up to 60 Hz): nearer, a tone cannot be told from the forced response in 4 s.
double freeFrequency(std::mt19937& rng, double lo, double hi) {
    std::uniform_real_distribution<double> f(lo, hi);
    for (;;) {
        const double v = f(rng);
        const auto near = [&](double step, double top) {
            const double k = std::round(v / step);
            return k >= 1 && k * step <= top + 0.2 && std::fabs(v - k * step) < 0.2;
        };
        if (!near(0.5, 10) && !near(3, 60)) return v;
    }
}

// Property: over random frequencies, shapes, phases and forced responses, a sustained
// oscillation is a limit cycle with its frequency within 5 %, the same oscillation decaying is
// not, and the forced response alone is not.
TEST(QuickReturnLimitCycle, SustainedIsDecayingAndForcedAreNot) {
    std::mt19937 rng(20240604);
    std::uniform_real_distribution<double> u(0, 1);
    const LimitCycleOptions o = experimentOneLike();
    for (int trial = 0; trial < 60; ++trial) {
        const double f = freeFrequency(rng, 1.2, 120);
        const double amp = 0.05 + 0.5 * u(rng), phase = kTwoPi * u(rng);
        // Non-sinusoidal: a third harmonic up to 0.3 of the fundamental (a relay's square wave
        // has 1/3).
        const double third = 0.3 * u(rng);
        const double noise = 0.02 * amp;
        const auto wave = [=](double t) {
            return std::sin(kTwoPi * f * t + phase) +
                   third * std::sin(3 * (kTwoPi * f * t + phase));
        };
        // Decay rate: the amplitude falls to at most e^-0.6 = 0.55 of itself from one half of
        // the window to the next (2 s).
        const double alpha = 0.3 + 2.7 * u(rng); // 1/s
        SCOPED_TRACE(testing::Message() << "trial " << trial << ": f " << f << " Hz, amplitude "
                                        << amp << ", third " << third << ", decay " << alpha);

        const auto sustained =
            forcedSignal(rng, 10, noise, [&](double t) { return amp * wave(t); });
        const LimitCycle s = detectLimitCycle(sustained, kDt, o);
        EXPECT_TRUE(s.detected) << s.verdict;
        EXPECT_NEAR(s.frequency_hz, f, 0.05 * f) << s.verdict;
        EXPECT_GE(s.ratio(), o.sustain_ratio);

        const auto decaying = forcedSignal(
            rng, 10, noise, [&](double t) { return amp * std::exp(-alpha * t) * wave(t); });
        const LimitCycle d = detectLimitCycle(decaying, kDt, o);
        EXPECT_FALSE(d.detected) << d.verdict;

        const auto forced = forcedSignal(rng, 10, noise, [](double) { return 0.0; });
        const LimitCycle n = detectLimitCycle(forced, kDt, o);
        EXPECT_FALSE(n.detected) << n.verdict;
    }
}

// The detector's floor and its refusals: a sustained oscillation below the floor is none, and a
// signal shorter than the window is refused with the reason.
TEST(QuickReturnLimitCycle, FloorAndShortSignals) {
    std::mt19937 rng(7);
    LimitCycleOptions o = experimentOneLike();
    const auto x =
        forcedSignal(rng, 10, 1e-6, [](double t) { return 1e-4 * std::sin(kTwoPi * 7.3 * t); });
    EXPECT_TRUE(detectLimitCycle(x, kDt, o).detected);
    o.min_amplitude = 1e-3;
    const LimitCycle below = detectLimitCycle(x, kDt, o);
    EXPECT_FALSE(below.detected);
    EXPECT_NE(below.verdict.find("below the floor"), std::string::npos) << below.verdict;
    const std::vector<double> shortSignal(100, 1.0);
    const LimitCycle s = detectLimitCycle(shortSignal, kDt, o);
    EXPECT_FALSE(s.detected);
    EXPECT_NE(s.verdict.find("too short"), std::string::npos) << s.verdict;
}

// The shipped paper-parameters job is the default job with the seed's printed masses and gains
// (paperParameters): same mechanism and plant otherwise, experiment 1, OSMC k1 = 40, k2 = 1.
TEST(QuickReturnPaper, JobHoldsTheSeedsPrintedFiguresOnTheProjectsMechanism) {
    const Job paper = loadJobFile(shippedJob("quick_return_paper_job.json"));
    const Job project = loadJobFile(shippedJob("quick_return_job.json"));
    const MachineModule& m = machineFor(paper);
    EXPECT_TRUE(m.validate(paper).empty()) << m.validate(paper)[0].message;
    const QuickReturnSpec& p = quickReturnSpec(paper);
    const QuickReturnSpec want = paperParameters(quickReturnSpec(project));
    EXPECT_EQ(json::write(m.writeSection(paper)), [&] {
        Job j = project;
        j.machine_spec.set(want);
        return json::write(m.writeSection(j));
    }());
    EXPECT_EQ(p.plant.slider_mass, kPaperSliderMass);
    EXPECT_EQ(p.gains.model_mass, kPaperSliderMass);
    EXPECT_EQ(p.gains.osmc_k1, 40);
    EXPECT_EQ(p.gains.osmc_k2, 1);
    EXPECT_EQ(p.gains.ffc_wn2, 1000);
    EXPECT_EQ(p.gains.ffc_xi, 1);
    EXPECT_EQ(p.experiment, Experiment::Tracking);
    // Eq. 36 prints b = 1/m5 = 2222.22 and the weight m5 g = 0.00441.
    EXPECT_NEAR(1 / p.gains.model_mass, 2222.22, 0.01);
    EXPECT_NEAR(p.gains.model_mass * p.gains.gravity, 0.00441, 5e-6);
}

// Experiment 1 with the paper's parameters runs for the four controllers and a short k2 sweep
// and gives finite figures; the sweep's verdict agrees with its own MSEs.
TEST(QuickReturnPaper, Experiment1StudyGivesFiniteFigures) {
    const Job paper = loadJobFile(shippedJob("quick_return_paper_job.json"));
    ExperimentSetup s;
    ASSERT_TRUE(buildSetup(quickReturnSpec(paper), &s).ok());
    K2Sweep sweep;
    sweep.points = 3;
    sweep.refine_steps = 2;
    const Experiment1Study st = studyExperiment1(s, sweep, 1e9);
    ASSERT_EQ(st.runs.size(), kAllControllers.size());
    for (size_t k = 0; k < st.runs.size(); ++k) {
        const Experiment1Run& r = st.runs[k];
        SCOPED_TRACE(toString(r.controller));
        EXPECT_EQ(r.controller, kAllControllers[k]);
        EXPECT_TRUE(std::isfinite(r.mse));
        EXPECT_GE(r.mse, 0);
        EXPECT_TRUE(std::isfinite(r.max_abs_error));
        EXPECT_TRUE(std::isfinite(r.max_torque));
        EXPECT_TRUE(std::isfinite(r.crank_turns));
        for (const LimitCycle* c : {&r.error_cycle, &r.sliding_cycle}) {
            EXPECT_TRUE(std::isfinite(c->frequency_hz)) << c->verdict;
            EXPECT_TRUE(std::isfinite(c->amplitude)) << c->verdict;
            EXPECT_GE(c->amplitude, 0);
            EXPECT_FALSE(c->verdict.empty());
        }
    }
    EXPECT_EQ(st.k1, 40);
    EXPECT_EQ(st.runs[3].k2, 1);
    EXPECT_EQ(st.rival_mse, std::min(st.runs[0].mse, st.runs[1].mse));
    ASSERT_EQ(st.sweep.size(), 3u);
    EXPECT_DOUBLE_EQ(st.sweep.front().k2, sweep.from);
    EXPECT_DOUBLE_EQ(st.sweep.back().k2, sweep.to);
    bool wins = false;
    for (const Experiment1Run& r : st.sweep) {
        EXPECT_TRUE(std::isfinite(r.mse));
        if (!wins && r.mse < st.rival_mse) {
            wins = true;
            EXPECT_EQ(st.smallest_k2, r.k2);
        }
    }
    EXPECT_EQ(st.osmc_wins, wins);
    if (wins) {
        EXPECT_LE(st.threshold_lo, st.threshold_hi);
    }
    // The report's text and JSON carry the study.
    const std::string text = experiment1StudyText(st, s);
    EXPECT_NE(text.find("OSMC k2 sweep at k1 = 40"), std::string::npos) << text;
    const json::Value j = experiment1StudyJson(st, s);
    ASSERT_NE(j.find("k2_sweep"), nullptr);
    EXPECT_EQ(j.find("k2_sweep")->asArray().size(), 3u);
}

// The sweep's bookkeeping where the OSMC does win (the project's job, k1 = 2000): the smallest
// winner is the first point under the rivals, the refined threshold brackets it from below.
TEST(QuickReturnPaper, SweepFindsTheSmallestWinningK2) {
    const Job project = loadJobFile(shippedJob("quick_return_job.json"));
    ExperimentSetup s;
    ASSERT_TRUE(buildSetup(quickReturnSpec(project), &s).ok());
    K2Sweep sweep;
    sweep.from = 1e-3;
    sweep.to = 1e3;
    sweep.points = 4;
    sweep.refine_steps = 2;
    const Experiment1Study st = studyExperiment1(s, sweep, 1e9);
    ASSERT_EQ(st.sweep.size(), 4u);
    size_t first = st.sweep.size();
    for (size_t i = 0; i < st.sweep.size(); ++i)
        if (first == st.sweep.size() && st.sweep[i].mse < st.rival_mse) first = i;
    EXPECT_EQ(st.osmc_wins, first < st.sweep.size());
    if (st.osmc_wins) {
        EXPECT_EQ(st.smallest_k2, st.sweep[first].k2);
        EXPECT_LE(st.threshold_lo, st.threshold_hi);
        EXPECT_LE(st.threshold_hi, st.smallest_k2);
        if (first > 0) {
            EXPECT_GE(st.threshold_lo, st.sweep[first - 1].k2);
        }
    }
    // Over the bound the sweep is skipped with the reason, the four runs stay.
    const Experiment1Study skipped = studyExperiment1(s, sweep, 1);
    EXPECT_EQ(skipped.runs.size(), 4u);
    EXPECT_TRUE(skipped.sweep.empty());
    EXPECT_NE(skipped.sweep_skipped.find("over the bound"), std::string::npos);
}

// `simulate` of a tracking job adds the study; the shipped cutting job's report has none.
TEST(QuickReturnPaper, OfflineReportAddsTheStudyForExperiment1Only) {
    for (const char* name : {"quick_return_paper_job.json", "quick_return_job.json"}) {
        const Job job = loadJobFile(shippedJob(name));
        const MachineModule& m = machineFor(job);
        std::string json, text;
        ASSERT_TRUE(m.offlineReport(job, m.plan(job), &json, &text).ok()) << name;
        const bool tracking = quickReturnSpec(job).experiment == Experiment::Tracking;
        EXPECT_EQ(json::parse(json).find("experiment1_study") != nullptr, tracking) << name;
        EXPECT_EQ(text.find("experiment 1 study") != std::string::npos, tracking) << name;
    }
}

} // namespace
} // namespace cutcell::quick_return
