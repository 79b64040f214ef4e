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

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace cutcell::test {
namespace {

struct SawCell {
    explicit SawCell(int pieces) {
        const MachineModule* m = findMachine(kFlyingSawId);
        job = m->defaultJob();
        job.machine_spec.as<FlyingSawSpec>()->queue = {{4000, pieces}};
        plan = m->plan(job, {});
        EXPECT_TRUE(plan.ok()) << plan.problem;
        std::string error;
        rig = makeSimulatedRig(job, *plan.program, &error);
        EXPECT_TRUE(rig) << error;
        EngineConfig c;
        c.clock = ClockMode::AsFastAsPossible;
        c.spec.runs_dir.clear();
        rig->configure(c);
        engine = std::make_unique<MotionEngine>(rig->devices(), c);
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

} // namespace
} // namespace cutcell::test
