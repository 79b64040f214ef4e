// The flying saw on the motion engine (fast clock) with its simulated rig: the job's program
// (a MasterAxis source) runs to completion on the line encoder, the cuts are measured on the
// pipe, the carriage is back at its wait position after every cycle, and feed hold / abort act
// as the engine's contract says.
#include "core/engine/motion_engine.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/machines/flying_saw/flying_saw_module.h"
#include "core/machines/flying_saw/flying_saw_source.h"
#include "devices/machines/sim_rig_registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>

namespace cutcell::test {
namespace {

// The carriage's feedback as a bus brings it: `late` cycles late, saying so in age_cycles
// (tell) or not. The drive itself is untouched: it follows its targets on time.
class LateFeedbackDrive : public AxisDrive {
  public:
    LateFeedbackDrive(AxisDrive* inner, int late, bool tell)
        : inner_(inner), late_(late), tell_(tell) {}
    void activate() override { inner_->activate(); }
    void deactivate() override { inner_->deactivate(); }
    void quickStop() override { inner_->quickStop(); }
    void faultReset() override { inner_->faultReset(); }
    DriveFeedback read(double now_s) override {
        ring_[static_cast<size_t>(n_ % kRing)] = inner_->read(now_s);
        const long back = std::min<long>(late_, n_);
        DriveFeedback f = ring_[static_cast<size_t>((n_ - back) % kRing)];
        f.state = ring_[static_cast<size_t>(n_ % kRing)].state; // the state is not the point
        f.age_cycles = static_cast<std::uint8_t>(tell_ ? back : 0);
        ++n_;
        return f;
    }
    void write(double q) override { inner_->write(q); }

  private:
    static constexpr long kRing = 64;
    AxisDrive* inner_;
    int late_;
    bool tell_;
    std::array<DriveFeedback, kRing> ring_{};
    long n_ = 0;
};

struct SawCell {
    explicit SawCell(int pieces, int carriageLate = 0, bool tellAge = true) {
        const MachineModule* m = findMachine(kFlyingSawId);
        job = m->defaultJob();
        job.machine_spec.as<FlyingSawSpec>()->queue = {{4000, pieces}};
        plan = m->plan(job, {});
        EXPECT_TRUE(plan.ok()) << plan.outcome.message;
        std::string error;
        rig = makeSimulatedRig(job, *plan.program, &error);
        EXPECT_TRUE(rig) << error;
        EngineConfig c;
        c.clock = ClockMode::AsFastAsPossible;
        c.spec = job.engine; // the saw's following-error limit in mm is the job's
        c.spec.runs_dir.clear();
        rig->configure(c);
        EngineDevices devices = rig->devices();
        if (carriageLate > 0) {
            late = std::make_unique<LateFeedbackDrive>(devices.axes[0], carriageLate, tellAge);
            devices.axes[0] = late.get();
        }
        engine = std::make_unique<MotionEngine>(devices, c);
        source = dynamic_cast<FlyingSawSource*>(plan.program->source.get());
    }
    bool bringUpAndStart() {
        engine->load(plan.program);
        engine->enable();
        engine->runCycles(2000, EngineState::Ready);
        engine->home();
        engine->runCycles(1, EngineState::Idle);
        engine->runCycles(200000, EngineState::Ready);
        engine->start();
        engine->runCycles(1, EngineState::Idle);
        return engine->state() == EngineState::Running;
    }
    std::string events() {
        std::string s;
        EngineEvent ev;
        while (engine->popEvent(ev))
            s += std::string(ev.text.data()) + "\n";
        return s;
    }
    Job job;
    MachinePlan plan;
    std::unique_ptr<MachineSimRig> rig;
    std::unique_ptr<LateFeedbackDrive> late;
    std::unique_ptr<MotionEngine> engine;
    FlyingSawSource* source = nullptr;
};

TEST(FlyingSawEngine, RunsThePiecesOnTheSimulatedRigAndMeasuresTheirLengths) {
    SawCell cell(6);
    ASSERT_TRUE(cell.bringUpAndStart()) << cell.events();
    std::string log;
    double worstReturn = 0;
    SawPhase prev = SawPhase::Waiting;
    for (int i = 0; i < 200000 && cell.engine->state() == EngineState::Running; ++i) {
        cell.engine->runCycles(1, static_cast<EngineState>(255));
        TelemetrySample t;
        while (cell.engine->popTelemetry(t)) {
            if (std::getenv("SAW_DEBUG") && t.time_s > 0.80 && t.time_s < 0.82)
                std::printf("%.3f sp2 %.9f act2 %.9f sp0 %.4f act0 %.4f\n", t.time_s, t.setpoint[2],
                            t.actual[2], t.setpoint[0], t.actual[0]);
        }
        const SawPhase ph = cell.source->phase();
        if (prev == SawPhase::Returning && ph != SawPhase::Returning)
            worstReturn = std::max(worstReturn, std::fabs(t.setpoint[0] - 0.0));
        prev = ph;
        if (i % 1000 == 0) log += cell.events();
    }
    log += cell.events();
    ASSERT_EQ(cell.engine->state(), EngineState::Completed) << log;
    EXPECT_LE(worstReturn, 1e-6);
    json::Value doc = json::Object{};
    cell.rig->addToReport(doc);
    const json::Value* lengths = doc.find("cut_lengths");
    ASSERT_NE(lengths, nullptr);
    EXPECT_EQ(lengths->find("pieces_measured")->asNumber(), 6);
    EXPECT_LE(std::fabs(lengths->find("error_mm_mean")->asNumber()), 0.1);
    EXPECT_LE(lengths->find("error_mm_max_abs")->asNumber(), 0.5);
    std::printf("%s\n", cell.rig->summary("completed").c_str());
}

// Runs the cell to its end; its tracking report.
TrackingReport runToEnd(SawCell& cell) {
    TrackingReport r;
    EXPECT_TRUE(cell.bringUpAndStart()) << cell.events();
    for (int i = 0; i < 200 && cell.engine->state() == EngineState::Running; ++i)
        cell.engine->runCycles(1000, static_cast<EngineState>(255));
    EXPECT_EQ(cell.engine->state(), EngineState::Completed) << cell.events();
    EXPECT_TRUE(cell.engine->lastRunReport(r));
    return r;
}

// The set-point of the next cycle (the telemetry drained first: the newest sample).
JointVector setpointNow(SawCell& cell) {
    TelemetrySample t{};
    while (cell.engine->popTelemetry(t)) {
    }
    cell.engine->runCycles(1, static_cast<EngineState>(255));
    while (cell.engine->popTelemetry(t)) {
    }
    return t.setpoint;
}

// The turntable turns half a turn a cut and has no end stops: after five pieces it stands five
// half turns on. Home takes it the short way to its reference (at most half a turn), and the
// next Start approaches its start the short way too; before, Home unwound every turn at the
// home speed (the walkthrough saw 120 s) and Start unwound them again.
TEST(FlyingSawEngine, TheTurntableHomesAndStartsTheShortWayAfterARun) {
    SawCell cell(5);
    runToEnd(cell);
    const double before = setpointNow(cell)[1];
    EXPECT_GT(before, 4.5 * kPi); // five half turns
    cell.engine->home();
    cell.engine->runCycles(1, EngineState::Idle);
    const std::uint64_t limit = 200000;
    std::uint64_t cycles = 0;
    while (cell.engine->state() == EngineState::Homing && cycles < limit)
        cycles += 1, cell.engine->runCycles(1, static_cast<EngineState>(255));
    ASSERT_EQ(cell.engine->state(), EngineState::Ready) << cell.events();
    const double homed = setpointNow(cell)[1];
    EXPECT_LE(std::fabs(homed - before), kPi + 1e-9);
    EXPECT_NEAR(std::remainder(homed, 2 * kPi), 0.0, 1e-9); // the reference's equivalent
    // Half a turn at the home speed, with its ramps: well under what five half turns took.
    const double halfTurnS = kPi / deg2rad(cell.job.engine.home_speed_deg_s);
    EXPECT_LE(static_cast<double>(cycles) * cell.job.sim.period_s, 1.5 * halfTurnS + 2.0)
        << cycles << " cycles";
    cell.engine->start();
    cell.engine->runCycles(1, EngineState::Idle);
    ASSERT_EQ(cell.engine->state(), EngineState::Running) << cell.events();
    double farthest = 0;
    for (int i = 0; i < 3000; ++i)
        farthest = std::max(farthest, std::fabs(setpointNow(cell)[1] - homed));
    EXPECT_LE(farthest, kPi + 1e-9); // the approach and the first cut: no unwinding
}

// Over a bus the feedback of a cycle can come cycles late (a TPDO held up on a loaded host).
// Told its age, the engine pairs it with the set-point of its own cycle: the carriage's
// tracking figures are those of feedback on time. Untold, the same drive shows the set-point's
// travel in the meantime as "following error" (what the CAN run reported before).
TEST(FlyingSawEngine, FeedbackCyclesLateIsComparedWithTheSetPointOfItsCycle) {
    SawCell onTime(2), told(2, 3, true), untold(2, 3, false);
    const TrackingReport a = runToEnd(onTime), b = runToEnd(told), c = runToEnd(untold);
    ASSERT_TRUE(a.linear(0));
    std::printf("carriage max |e| / rms (mm): on time %.4f / %.4f, 3 cycles late told %.4f / "
                "%.4f, untold %.4f / %.4f\n",
                a.maxAbs(0), a.rms(0), b.maxAbs(0), b.rms(0), c.maxAbs(0), c.rms(0));
    // The same pairs, shifted by 3 of ~15000 samples.
    EXPECT_NEAR(b.maxAbs(0), a.maxAbs(0), 1e-9 + 1e-3 * a.maxAbs(0));
    EXPECT_NEAR(b.rms(0), a.rms(0), 0.01 * a.rms(0));
    // Untold: more by at least a quarter of 3 cycles' travel at the carriage's speed limit.
    const double period = onTime.job.sim.period_s;
    const double vReturn = onTime.job.machine_spec.as<FlyingSawSpec>()->carriage.max_speed_mm_s;
    EXPECT_GT(c.maxAbs(0), a.maxAbs(0) + 0.25 * 3 * period * vReturn);
}

// As late as a bus drive's feedback stays valid (100 ms without a TPDO is stale): 40 cycles at
// 1 ms, more than the 16 the engine once kept, is still paired with the set-point of its cycle.
TEST(FlyingSawEngine, FeedbackFortyCyclesLateIsStillPairedWithItsCycle) {
    SawCell onTime(2), told(2, 40, true);
    ASSERT_LE(40 * onTime.job.sim.period_s, 0.1);
    const TrackingReport a = runToEnd(onTime), b = runToEnd(told);
    ASSERT_TRUE(a.linear(0));
    std::printf("carriage max |e| / rms (mm): on time %.4f / %.4f, 40 cycles late told %.4f / "
                "%.4f\n",
                a.maxAbs(0), a.rms(0), b.maxAbs(0), b.rms(0));
    EXPECT_NEAR(b.maxAbs(0), a.maxAbs(0), 1e-9 + 1e-3 * a.maxAbs(0));
    EXPECT_NEAR(b.rms(0), a.rms(0), 0.01 * a.rms(0));
}

} // namespace
} // namespace cutcell::test
