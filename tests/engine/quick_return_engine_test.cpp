// The quick-return cutter in the engine: its crank in torque mode under the control law on the
// simulated mechanism (fast clock): strokes with the open-loop return unsupervised, and an
// emergency stop that removes the torque within one cycle.
#include "core/engine/motion_engine.h"
#include "core/machine/machine_registry.h"
#include "core/machines/quick_return/quick_return_module.h"
#include "devices/machines/quick_return_sim_rig.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cutcell::test {
namespace {

struct QrCell {
    explicit QrCell(StopCategory cat = StopCategory::Cat0) {
        module = findMachine(kQuickReturnId);
        job = module->defaultJob();
        plan = module->plan(job, "");
        const auto* data = static_cast<const QuickReturnPlanData*>(plan.data.get());
        rig = std::make_unique<QuickReturnSimRig>(data->setup, *plan.program);
        EngineConfig c;
        c.clock = ClockMode::AsFastAsPossible;
        c.spec.runs_dir.clear();
        c.spec.estop_category = cat;
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

TEST(QuickReturnEngine, InvalidScaleIsAFaultWithTorqueOff) {
    QrCell cell;
    ASSERT_TRUE(cell.until([&] { return cell.law().phase() == quick_return::QrPhase::Cut; }));
    cell.rig->sensor().injectInvalid(true);
    cell.engine->runCycles(1, static_cast<EngineState>(255));
    EXPECT_EQ(cell.engine->state(), EngineState::Fault);
    EXPECT_EQ(cell.rig->drive().appliedTorque(), 0);
}

} // namespace
} // namespace cutcell::test
