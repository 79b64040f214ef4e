// The engine thread's real-time set-up is checked and reported (never silent), and the host
// wake-up latency check measures what it says. No timing bounds: figures are in the bench.
#include "core/engine/host_latency.h"
#include "core/engine/motion_engine.h"
#include "core/engine/realtime_thread.h"
#include "devices/sim/simulated_drive.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <pthread.h>
#include <sched.h>
#include <string>
#include <string_view>
#include <thread>
#include <tuple>

using namespace cutcell;

namespace {

// Whether this process may use SCHED_FIFO at `priority` (asked on a throw-away thread).
bool fifoAllowed(int priority) {
    bool ok = false;
    std::thread t([&] {
        sched_param sp{};
        sp.sched_priority = priority;
        ok = pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp) == 0;
    });
    t.join();
    return ok;
}

struct RealtimeRun {
    RealtimeStatus status;
    std::string text;
    Severity severity = Severity::Info;
    bool eventSeen = false;
};

RealtimeRun runEngineThread(const RealtimeSettings& s) {
    EngineDevices none; // no axes: the cycle idles
    EngineConfig c;
    c.clock = ClockMode::RealTime;
    c.realtime = s;
    MotionEngine engine(none, c);
    engine.startThread();
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    RealtimeRun r;
    while (!r.eventSeen && std::chrono::steady_clock::now() < end) {
        EngineEvent e;
        while (engine.popEvent(e))
            if (std::strncmp(e.text.data(), "Real-time:", 10) == 0) {
                r.eventSeen = true;
                r.text = e.text.data();
                r.severity = e.severity;
            }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    engine.stopThread();
    r.status = engine.realtimeStatus();
    return r;
}

} // namespace

TEST(Realtime, EngineReportsWhetherFifoWasGranted) {
    RealtimeSettings s;
    s.lock_memory = false;
    s.priority = 10;
    const RealtimeRun r = runEngineThread(s);
    ASSERT_TRUE(r.eventSeen);
    EXPECT_TRUE(r.status.applied);
    // What the engine reports is what the OS grants this process.
    EXPECT_EQ(r.status.rt_priority_granted, fifoAllowed(10)) << r.text;
    if (r.status.rt_priority_granted) {
        EXPECT_EQ(r.status.priority, 10);
        EXPECT_EQ(r.severity, Severity::Info) << r.text;
    } else {
        EXPECT_NE(r.status.priority_error, 0);
        EXPECT_EQ(r.severity, Severity::Warning) << r.text;
        EXPECT_NE(r.text.find("NOT granted"), std::string::npos) << r.text;
    }
}

TEST(Realtime, RefusedSettingIsAWarningThatNamesIt) {
    RealtimeSettings s;
    s.lock_memory = false;
    s.priority = 0;      // normal scheduler: nothing to refuse there
    s.cpu = CPU_SETSIZE; // no such CPU
    const RealtimeRun r = runEngineThread(s);
    ASSERT_TRUE(r.eventSeen);
    EXPECT_FALSE(r.status.cpu_pinned);
    EXPECT_NE(r.status.cpu_error, 0);
    EXPECT_FALSE(r.status.rt_priority_granted);
    EXPECT_EQ(r.severity, Severity::Warning);
    EXPECT_NE(r.text.find("NOT pinned to CPU"), std::string::npos) << r.text;
    EXPECT_NE(r.text.find("normal scheduler"), std::string::npos) << r.text;
}

// Every step refused with the OS's reasons: a line longer than an event holds. Its pieces fit
// an event each, are cut between items and give the whole line back.
TEST(Realtime, ALongLineGoesOutInWholeItems) {
    RealtimeSettings asked;
    asked.priority = 80;
    asked.lock_memory = true;
    asked.cpu = 1;
    asked.cpu_dma_latency = true;
    RealtimeStatus refused;
    refused.priority_error = EPERM;
    refused.lock_error = EAGAIN;
    refused.cpu_error = EINVAL;
    refused.dma_latency_error = EACCES;
    char line[640];
    ASSERT_FALSE(describeRealtime(asked, refused, line, sizeof line));
    const std::size_t eventChars = std::tuple_size_v<decltype(EngineEvent::text)> - 1;
    std::string_view rest(line);
    ASSERT_GT(rest.size(), eventChars) << line; // else this test tests nothing
    std::string joined;
    int pieces = 0;
    while (!rest.empty()) {
        const std::size_t n = realtimeLinePiece(rest, eventChars);
        ASSERT_GT(n, 0u);
        ASSERT_LE(n, eventChars);
        const std::string_view piece = rest.substr(0, n);
        EXPECT_NE(piece.back(), ';') << piece;
        joined += (pieces++ ? "; " : "") + std::string(piece);
        rest.remove_prefix(n);
        if (!rest.empty()) {
            ASSERT_EQ(rest.substr(0, 2), "; ") << rest; // cut between items only
            rest.remove_prefix(2);
        }
    }
    EXPECT_EQ(pieces, 2);
    EXPECT_EQ(joined, line);
    EXPECT_NE(joined.find("/dev/cpu_dma_latency NOT held"), std::string::npos) << joined;
}

TEST(Realtime, PinningToAnExistingCpuIsGranted) {
    RealtimeSettings s;
    s.lock_memory = false;
    s.priority = 0;
    s.cpu = 0;
    const RealtimeRun r = runEngineThread(s);
    ASSERT_TRUE(r.eventSeen);
    EXPECT_TRUE(r.status.cpu_pinned) << r.text;
    EXPECT_EQ(r.severity, Severity::Info) << r.text;
}

TEST(Realtime, FastClockDoesNoRealtimeSetUp) {
    EngineDevices none;
    EngineConfig c;
    c.clock = ClockMode::AsFastAsPossible;
    MotionEngine engine(none, c);
    engine.runCycles(10, EngineState::Fault);
    EXPECT_FALSE(engine.realtimeStatus().applied);
}

TEST(HostLatency, MeasuresOneSamplePerPeriodOrFewer) {
    RealtimeSettings s;
    s.lock_memory = false;
    s.priority = 0;
    const HostLatency h = measureHostWakeupLatency(0.001, 0.2, s);
    EXPECT_TRUE(h.realtime.applied);
    // At most one wake-up per period (missed deadlines are skipped, as cyclictest does).
    EXPECT_GT(h.samples, 0u);
    EXPECT_LE(h.samples, 200u);
    EXPECT_GE(h.p50_us, 0);
    EXPECT_LE(h.p50_us, h.p99_us);
    EXPECT_LE(h.p99_us, h.max_us + 1); // bins are 1 us wide, reported at their upper edge
}
