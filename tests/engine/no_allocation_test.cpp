// The cycle does not allocate: global operator new is counted while the engine runs cycles
// through a whole job (enable, home, cut with feed hold / resume / override, fault, emergency
// stop, reset). Its own executable: replacing operator new is program-wide.
#include "engine_fixture.h"

#include <atomic>
#include <cstdlib>
#include <new>
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

// Runs n cycles with allocation counting on (consumers drain between chunks, uncounted).
long cyclesCounted(SimCell& cell, std::uint64_t n) {
    long total = 0;
    for (std::uint64_t done = 0; done < n; done += 30) {
        g_allocations.store(0);
        g_counting.store(true);
        cell.engine().runCycles(30, static_cast<EngineState>(255)); // no state stops it early
        g_counting.store(false);
        total += g_allocations.load();
        TelemetrySample t;
        while (cell.engine().popTelemetry(t)) {
        }
        EngineEvent e;
        while (cell.engine().popEvent(e)) {
        }
    }
    return total;
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

} // namespace
} // namespace cutcell::test
