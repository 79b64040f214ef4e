// The cycle does not allocate: global operator new is counted while the engine runs cycles
// through a whole job (enable, home, cut with feed hold / resume / override, fault, emergency
// stop, reset). Its own executable: replacing operator new is program-wide.
#include "engine_fixture.h"

#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "devices/machines/sim_rig_registry.h"
#include "devices/sim/follower_rig.h"
#include "devices/sim/slider_rig.h"

#include <atomic>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

void* countedAlloc(std::size_t n) {
    if (g_counting.load(std::memory_order_relaxed))
        g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
} // namespace

void* operator new(std::size_t n) {
    return countedAlloc(n);
}
void* operator new[](std::size_t n) {
    return countedAlloc(n);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}

namespace cutcell::test {
namespace {

std::string g_events; // the events seen by cyclesCounted (for failure messages)

// Runs n cycles with allocation counting on (consumers drain between chunks, uncounted).
long cyclesCounted(MotionEngine& engine, std::uint64_t n) {
    long total = 0;
    for (std::uint64_t done = 0; done < n; done += 30) {
        g_allocations.store(0);
        g_counting.store(true);
        engine.runCycles(30, static_cast<EngineState>(255)); // no state stops it early
        g_counting.store(false);
        total += g_allocations.load();
        TelemetrySample t;
        while (engine.popTelemetry(t)) {
        }
        EngineEvent e;
        while (engine.popEvent(e))
            g_events += std::string(e.text.data()) + "\n";
    }
    return total;
}
long cyclesCounted(SimCell& cell, std::uint64_t n) {
    return cyclesCounted(cell.engine(), n);
}

EngineConfig fastConfig() {
    EngineConfig c;
    c.clock = ClockMode::AsFastAsPossible;
    c.spec.runs_dir.clear();
    return c;
}

TEST(EngineCycle, AllocationCounterSeesAllocations) {
    g_allocations.store(0);
    g_counting.store(true);
    auto* v = new std::vector<int>(100);
    g_counting.store(false);
    delete v;
    EXPECT_GE(g_allocations.load(), 2);
}

TEST(EngineCycle, DoesNotAllocateThroughAWholeJob) {
    SimCell cell;
    MotionEngine& e = cell.engine();
    long allocations = 0;
    e.enable();
    allocations += cyclesCounted(cell, 100);
    e.home();
    allocations += cyclesCounted(cell, 4000);
    e.jog(1, deg2rad(2));
    allocations += cyclesCounted(cell, 1000);
    e.home();
    allocations += cyclesCounted(cell, 1000);
    ASSERT_EQ(e.state(), EngineState::Ready);
    e.start();
    allocations += cyclesCounted(cell, 10000); // approach, settle, ignition, cutting
    ASSERT_EQ(e.state(), EngineState::Running);
    e.setOverride(1.4);
    allocations += cyclesCounted(cell, 1000);
    e.feedHold();
    allocations += cyclesCounted(cell, 1500);
    EXPECT_EQ(e.state(), EngineState::Paused);
    e.resume();
    allocations += cyclesCounted(cell, 1500);
    e.abort();
    allocations += cyclesCounted(cell, 1500);
    EXPECT_EQ(e.state(), EngineState::Ready);
    cell.drive(2).injectFault(0x5441);
    allocations += cyclesCounted(cell, 60);
    EXPECT_EQ(e.state(), EngineState::Fault);
    e.emergencyStop();
    allocations += cyclesCounted(cell, 60);
    e.releaseEmergencyStop();
    e.reset();
    allocations += cyclesCounted(cell, 60);
    EXPECT_EQ(e.state(), EngineState::Idle);
    EXPECT_EQ(allocations, 0);
}

// A program with a set-point correction (the robot's torch height control) on the simulated
// cell whose arc voltage follows an out-of-round pipe: the THC, the IK it solves each cycle and
// the simulated arc run in the cycle, through a feed hold and to the end of the run.
TEST(EngineCycle, TorchHeightControlDoesNotAllocate) {
    const Job job =
        loadJobFile(std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/plasma_thc_job.json");
    const MachinePlan plan = findMachine(job.machine)->plan(job, {});
    ASSERT_TRUE(plan.ok()) << plan.outcome.message;
    ASSERT_TRUE(plan.program->correction);
    std::string error;
    const auto rig = makeSimulatedRig(job, *plan.program, &error);
    ASSERT_TRUE(rig) << error;
    EngineConfig c = fastConfig();
    c.spec = job.engine;
    c.spec.runs_dir.clear();
    rig->configure(c);
    MotionEngine e(rig->devices(), c);
    e.load(plan.program);
    long allocations = 0;
    e.enable();
    allocations += cyclesCounted(e, 2000);
    e.home();
    allocations += cyclesCounted(e, 30000);
    ASSERT_EQ(e.state(), EngineState::Ready) << g_events;
    e.start();
    allocations += cyclesCounted(e, 4000); // approach, ignition, the pierce, cutting
    e.feedHold();
    allocations += cyclesCounted(e, 1500);
    e.resume();
    for (int k = 0; k < 40 && e.state() != EngineState::Completed; ++k)
        allocations += cyclesCounted(e, 1500); // the run lasts the job's sim.duration_s
    EXPECT_EQ(e.state(), EngineState::Completed) << g_events;
    EXPECT_EQ(allocations, 0);
}

// The master-axis source: sync-in, in sync, a cam table and a cut length replaced while
// running, feed hold (finish, return, rest), resume, abort, fault, emergency stop, reset.
TEST(EngineCycle, MasterSourceDoesNotAllocate) {
    FollowerRigOptions o;
    o.line.speed_mm_s = 200;
    o.line.speed_amplitude = 0.1;
    o.line.noise_mm = 0.005;
    o.follower.first_sync = 300;
    o.follower.start_distance = 60;
    o.follower.sync_span = 1000; // in sync from ~1.5 s to ~6.5 s of engine time
    o.follower.cut_length = 500;
    o.follower.cut_count = 50;
    o.follower.return_s = 0.5;
    FollowerRig rig(o);
    EngineConfig c = fastConfig();
    rig.configure(c);
    MotionEngine e(rig.devices(), c);
    e.load(rig.program());
    long allocations = 0;
    e.enable();
    allocations += cyclesCounted(e, 60);
    e.home();
    allocations += cyclesCounted(e, 600);
    ASSERT_EQ(e.state(), EngineState::Ready);
    e.start();
    allocations += cyclesCounted(e, 2500); // approach, settle, saw at speed, sync-in, in sync
    ASSERT_EQ(rig.follower().state(), SyncState::InSync) << g_events;
    auto* back = rig.follower().camTables().beginWrite();
    ASSERT_NE(back, nullptr);
    (*back)[0] = feedStrokeCam(40, o.cam_period_mm);
    rig.follower().camTables().publish();
    rig.follower().setCutLength(450);
    allocations += cyclesCounted(e, 3000);
    e.feedHold();
    allocations += cyclesCounted(e, 3000);
    EXPECT_EQ(e.state(), EngineState::Paused) << g_events;
    e.resume();
    allocations += cyclesCounted(e, 3000);
    e.abort();
    allocations += cyclesCounted(e, 1500);
    EXPECT_EQ(e.state(), EngineState::Ready);
    rig.carriage().injectFault(0x5441);
    allocations += cyclesCounted(e, 60);
    EXPECT_EQ(e.state(), EngineState::Fault);
    e.emergencyStop();
    allocations += cyclesCounted(e, 60);
    rig.carriage().clearInjections();
    e.releaseEmergencyStop();
    e.reset();
    allocations += cyclesCounted(e, 60);
    EXPECT_EQ(e.state(), EngineState::Idle);
    EXPECT_EQ(allocations, 0);
}

// The control-law source: tracking (home), strokes with open-loop returns and supervision
// events, feed hold, resume, sensor fault, reset, emergency stop.
TEST(EngineCycle, ControlLawSourceDoesNotAllocate) {
    SliderRigOptions o;
    o.law.stroke_count = 100;
    SliderRig rig(o);
    EngineConfig c = fastConfig();
    c.spec.estop_category = StopCategory::Cat1;
    rig.configure(c);
    MotionEngine e(rig.devices(), c);
    e.load(rig.program());
    long allocations = 0;
    e.enable();
    allocations += cyclesCounted(e, 60);
    e.home();
    allocations += cyclesCounted(e, 300);
    ASSERT_EQ(e.state(), EngineState::Ready);
    e.start();
    allocations += cyclesCounted(e, 6000);
    e.setOverride(0.5);
    e.feedHold();
    allocations += cyclesCounted(e, 3000);
    e.resume();
    allocations += cyclesCounted(e, 3000);
    EXPECT_EQ(e.state(), EngineState::Running);
    rig.sensor().injectInvalid(true);
    allocations += cyclesCounted(e, 60);
    EXPECT_EQ(e.state(), EngineState::Fault);
    rig.sensor().injectInvalid(false);
    e.reset();
    allocations += cyclesCounted(e, 60);
    e.enable();
    allocations += cyclesCounted(e, 60);
    e.emergencyStop();
    allocations += cyclesCounted(e, 600);
    EXPECT_EQ(e.state(), EngineState::EmergencyStop);
    EXPECT_EQ(allocations, 0);
}

} // namespace
} // namespace cutcell::test
