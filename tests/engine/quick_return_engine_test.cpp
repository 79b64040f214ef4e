// The quick-return cutter in the engine: its crank in torque mode under the control law on the
// simulated mechanism (fast clock): strokes with the open-loop return unsupervised, and an
// emergency stop that removes the torque within one cycle; the run's figures from its telemetry
// against the mechanism's true motion.
#include "core/engine/motion_engine.h"
#include "core/machine/machine_registry.h"
#include "core/machines/quick_return/quick_return_module.h"
#include "core/machines/quick_return/run_figures.h"
#include "devices/machines/quick_return/quick_return_sim_rig.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

namespace cutcell::test {
namespace {

struct QrCell {
    // contact: the 400 N of Eq. 40 over the workpiece (as the application's rig for a cutting
    // job, makeQuickReturnSimRig); off by default.
    explicit QrCell(StopCategory cat = StopCategory::Cat0, std::uint32_t telemetryEvery = 1,
                    bool contact = false) {
        module = findMachine(kQuickReturnId);
        job = module->defaultJob();
        plan = module->plan(job, "");
        const auto* data = static_cast<const QuickReturnPlanData*>(plan.data.get());
        quick_return::ExperimentSetup setup = data->setup;
        setup.plant.contact = contact;
        rig = std::make_unique<QuickReturnSimRig>(setup, *plan.program);
        EngineConfig c;
        c.clock = ClockMode::AsFastAsPossible;
        if (contact) c.spec = job.engine; // its following-error limit allows for the impact
        c.spec.runs_dir.clear();
        c.spec.estop_category = cat;
        c.telemetry_every_n_cycles = telemetryEvery;
        rig->configure(c);
        engine = std::make_unique<MotionEngine>(rig->devices(), c);
        EXPECT_TRUE(engine->load(plan.program));
        engine->enable();
        engine->runCycles(2000, EngineState::Ready);
        engine->home();
        engine->runCycles(1, EngineState::Idle);
        engine->runCycles(200000, EngineState::Ready);
        EXPECT_EQ(engine->state(), EngineState::Ready);
        engine->start();
        engine->runCycles(1, EngineState::Idle);
    }
    const quick_return::QuickReturnLaw& law() const {
        return *static_cast<const quick_return::QuickReturnLaw*>(plan.program->source.get());
    }
    // Runs until pred() or max cycles; false on time-out.
    template <class P> bool until(P pred, int max = 100000) {
        for (int i = 0; i < max; ++i) {
            engine->runCycles(1, static_cast<EngineState>(255));
            if (pred()) return true;
        }
        return false;
    }
    const MachineModule* module = nullptr;
    Job job;
    MachinePlan plan;
    std::unique_ptr<QuickReturnSimRig> rig;
    std::unique_ptr<MotionEngine> engine;
};

TEST(QuickReturnEngine, CutsItsStrokesWithTheCrankInTorqueMode) {
    QrCell cell;
    ASSERT_EQ(cell.engine->state(), EngineState::Running);
    ASSERT_TRUE(cell.until([&] { return cell.engine->state() != EngineState::Running; }, 20000));
    EXPECT_EQ(cell.engine->state(), EngineState::Completed);
    EXPECT_EQ(cell.law().strokesDone(), quickReturnSpec(cell.job).strokes);
}

TEST(QuickReturnEngine, EmergencyStopRemovesTorqueWithinOneCycle) {
    QrCell cell;
    ASSERT_TRUE(cell.until([&] {
        return cell.law().phase() == quick_return::QrPhase::Cut &&
               cell.rig->drive().appliedTorque() != 0;
    }));
    const std::uint64_t writes = cell.rig->drive().writes();
    cell.engine->emergencyStop();
    int cycles = 0;
    while (cell.rig->drive().appliedTorque() != 0 && cycles < 100) {
        cell.engine->runCycles(1, static_cast<EngineState>(255));
        ++cycles;
    }
    EXPECT_EQ(cycles, 1) << "torque removed in the first cycle after the request";
    EXPECT_EQ(cell.rig->drive().writes(), writes + 1);
    EXPECT_EQ(cell.engine->state(), EngineState::EmergencyStop);
    EXPECT_EQ(cell.rig->drive().read(0).state, DriveState::Disabled);
}

// Runs `stop` on a cell in each phase of the stroke (with and without the cutting force) and
// expects the crank out of Running within 1.5 s; then `after` (may be empty) on that cell.
template <class Stop, class After> void stopInEveryPhase(const char* what, Stop stop, After after) {
    using quick_return::QrPhase;
    for (const bool contact : {false, true})
        for (const QrPhase at : {QrPhase::ReturnPush, QrPhase::ReturnBrake, QrPhase::Cut}) {
            SCOPED_TRACE(std::string(toString(at)) + (contact ? ", with contact" : ""));
            QrCell cell(StopCategory::Cat0, 1, contact);
            ASSERT_TRUE(cell.until([&] { return cell.law().phase() == at; }, 20000));
            stop(*cell.engine);
            EXPECT_TRUE(
                cell.until([&] { return cell.engine->state() != EngineState::Running; }, 1500))
                << "still " << toString(cell.engine->state()) << " in "
                << toString(cell.law().phase()) << " 1.5 s after the " << what;
            after(cell);
        }
}

// A feed hold in any phase of the stroke brings the crank to rest (Paused) within 1.5 s — the
// cut or the open-loop return it came in is finished first — and Resume goes on to the last
// stroke. The operator station's walkthrough found the hold in the open-loop return (64 ms
// after Start) never coming to rest: still Running 20 s later; braked half-way, a resume then
// ended the run at once (Completed after 0 of 3 strokes).
TEST(QuickReturnEngine, FeedHoldInEveryPhaseComesToRestAndResumes) {
    stopInEveryPhase(
        "hold", [](MotionEngine& e) { e.feedHold(); },
        [](QrCell& cell) {
            ASSERT_EQ(cell.engine->state(), EngineState::Paused);
            cell.engine->resume();
            ASSERT_TRUE(cell.until(
                [&] {
                    return cell.engine->state() != EngineState::Running &&
                           cell.engine->state() != EngineState::Paused;
                },
                30000));
            std::string events;
            for (EngineEvent e; cell.engine->popEvent(e);)
                events += std::string(e.text.data()) + "\n";
            EXPECT_EQ(cell.engine->state(), EngineState::Completed) << events;
            EXPECT_EQ(cell.law().strokesDone(), quickReturnSpec(cell.job).strokes);
        });
}

// Abort in any phase of the stroke brings the crank to rest within 1.5 s (the CI walkthrough
// of 2026-12-03 saw the crank Running at stroke 1 of 3 over 20 s after F8 twice).
TEST(QuickReturnEngine, AbortInEveryPhaseComesToRest) {
    stopInEveryPhase(
        "abort", [](MotionEngine& e) { e.abort(); }, [](QrCell&) {});
}

TEST(QuickReturnEngine, InvalidScaleIsAFaultWithTorqueOff) {
    QrCell cell;
    ASSERT_TRUE(cell.until([&] { return cell.law().phase() == quick_return::QrPhase::Cut; }));
    cell.rig->sensor().injectInvalid(true);
    cell.engine->runCycles(1, static_cast<EngineState>(255));
    EXPECT_EQ(cell.engine->state(), EngineState::Fault);
    EXPECT_EQ(cell.rig->drive().appliedTorque(), 0);
}

// The figures of a whole cutting run from its telemetry, and the truth of every cycle: the
// slider's true position and velocity (the plant's, at the cycle's read) and the law's
// reference.
struct FiguresAndTruth {
    quick_return::RunFigureStats stats;
    double yRefError = 0, dyRefError = 0; // max |figures' y_d - law's y_d| (m, m/s)
    int compared = 0;                     // cutting points compared with the law
    double truthMax = 0, truthRms = 0;
    int truthInWork = 0;
    int strokes = 0;
};

FiguresAndTruth runWithFigures(std::uint32_t telemetryEvery) {
    QrCell cell(StopCategory::Cat0, telemetryEvery, true);
    quick_return::RunFigures figures(cell.law().config());
    const auto& lc = cell.law().config();
    const double lo = std::min(lc.profile.y_a, lc.profile.y_b);
    const double hi = std::max(lc.profile.y_a, lc.profile.y_b);
    struct Truth {
        double y_d, dy_d;
    };
    std::map<long long, Truth> lawRef; // by cycle time (us)
    FiguresAndTruth out;
    double sum = 0;
    TelemetrySample s;
    for (int i = 0; i < 20000 && cell.engine->state() == EngineState::Running; ++i) {
        const auto& plant = cell.rig->drive().plant();
        const double y = plant.sliderPosition(), dy = plant.sliderVelocity();
        cell.engine->runCycles(1, static_cast<EngineState>(255));
        const quick_return::QrSample& q = cell.law().last();
        bool sampled = false;
        while (cell.engine->popTelemetry(s)) {
            figures.add(s);
            sampled = true;
        }
        if (q.phase == quick_return::QrPhase::Cut) {
            // (In the cycle that enters the cut the law's sample is the return's: y_d = y.)
            if (sampled && q.t > 0) lawRef[std::llround(s.elapsed_s * 1e6)] = {q.y_d, q.dy_d};
            if (y >= lo && y <= hi) {
                const double e = q.dy_d - dy;
                out.truthMax = std::max(out.truthMax, std::fabs(e));
                sum += e * e;
                ++out.truthInWork;
            }
        }
    }
    EXPECT_EQ(cell.engine->state(), EngineState::Completed);
    while (cell.engine->popTelemetry(s))
        figures.add(s);
    figures.flush();
    out.truthRms = out.truthInWork > 0 ? std::sqrt(sum / out.truthInWork) : 0;
    out.stats = figures.stats();
    out.strokes = cell.law().strokesDone();
    for (const quick_return::RunFigurePoint& p : figures.points()) {
        if (!p.cutting) continue;
        const auto it = lawRef.find(std::llround(p.t * 1e6));
        if (it == lawRef.end()) continue;
        out.yRefError = std::max(out.yRefError, std::fabs(p.y_d - it->second.y_d));
        out.dyRefError = std::max(out.dyRefError, std::fabs(p.dy_d - it->second.dy_d));
        ++out.compared;
    }
    return out;
}

void print(const char* what, const FiguresAndTruth& f) {
    std::printf("%s: y_d off by %.3g m, y_d' by %.3g m/s over %d cutting samples; in the work: "
                "figures %d samples, |e'| max %.4f rms %.4f m/s; truth %d, max %.4f rms %.4f\n",
                what, f.yRefError, f.dyRefError, f.compared, f.stats.samples_in_work,
                f.stats.velocity_error_max, f.stats.velocity_error_rms, f.truthInWork, f.truthMax,
                f.truthRms);
}

// Telemetry every cycle: the reference is the law's own, the velocity error's figures those of
// the plant's true velocity (measured 1.4 % on the max, 0.4 % on the RMS: the central
// difference is 2 ms wide across the impact at y_a).
TEST(QuickReturnEngine, RunFiguresFromTelemetryMatchTheMechanism) {
    const FiguresAndTruth f = runWithFigures(1);
    print("telemetry every cycle", f);
    EXPECT_EQ(f.stats.cuts, f.strokes);
    EXPECT_GT(f.compared, 1000);
    EXPECT_LT(f.yRefError, 1e-9);
    EXPECT_LT(f.dyRefError, 1e-9);
    ASSERT_GT(f.truthInWork, 100);
    EXPECT_NEAR(f.stats.samples_in_work, f.truthInWork, 2);
    EXPECT_NEAR(f.stats.velocity_error_max, f.truthMax, 0.03 * f.truthMax);
    EXPECT_NEAR(f.stats.velocity_error_rms, f.truthRms, 0.02 * f.truthRms);
}

// Every 10th cycle (the fast clock's telemetry): the stroke's start is still found exactly
// from the supervised set-point; the velocity is a 20 ms difference, so the impact's peak is
// smoothed (measured RMS 10 % low, max 30 % low), never exaggerated.
TEST(QuickReturnEngine, RunFiguresFromDecimatedTelemetryKeepTheReference) {
    const FiguresAndTruth f = runWithFigures(10);
    print("telemetry every 10th cycle", f);
    EXPECT_EQ(f.stats.cuts, f.strokes);
    EXPECT_GT(f.compared, 100);
    EXPECT_LT(f.yRefError, 1e-9);
    EXPECT_LT(f.dyRefError, 1e-9);
    EXPECT_NEAR(f.stats.samples_in_work, f.truthInWork / 10, 3);
    EXPECT_LE(f.stats.velocity_error_max, 1.02 * f.truthMax);
    EXPECT_NEAR(f.stats.velocity_error_rms, f.truthRms, 0.15 * f.truthRms);
}

} // namespace
} // namespace cutcell::test
