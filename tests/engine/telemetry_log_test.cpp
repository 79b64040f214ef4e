// Telemetry drained at 30 Hz loses nothing; each run leaves a complete run log.
#include "engine_fixture.h"

#include "core/engine/run_log.h"
#include "core/job/job_io.h"
#include "core/json/json.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <unistd.h>

namespace cutcell::test {
namespace {

namespace fs = std::filesystem;

TEST(Telemetry, NoSampleLostWhenDrainedAt30HzOfEngineTime) {
    SimCell cell;
    cell.engine().enable();
    MotionEngine& e = cell.engine();
    // A 30 Hz consumer against a 1 kHz cycle: drain every 34 cycles through a whole run.
    std::uint64_t samples = 0;
    int stage = 0; // 0: enabling, 1: homing, 2: cutting
    TelemetrySample t;
    double lastTime = -1;
    while (e.state() != EngineState::Completed && e.cycleStats().cycles < 100000) {
        e.runCycles(34, EngineState::Completed);
        while (e.popTelemetry(t)) {
            ++samples;
            ASSERT_GT(t.time_s, lastTime) << "in order, no repeats";
            lastTime = t.time_s;
        }
        EngineEvent ev;
        while (e.popEvent(ev)) {
        }
        if (e.state() == EngineState::Ready && stage == 0) {
            e.home();
            stage = 1;
        } else if (e.state() == EngineState::Ready && stage == 1 && t.homed) {
            e.start();
            stage = 2;
        }
    }
    ASSERT_EQ(e.state(), EngineState::Completed);
    // The last sample: the whole path done, nothing remaining, the run's time since Start.
    EXPECT_EQ(t.state, EngineState::Completed);
    EXPECT_DOUBLE_EQ(t.progress, 1.0);
    EXPECT_DOUBLE_EQ(t.remaining_s, 0.0);
    EXPECT_EQ(t.point_index + 1, t.point_count);
    EXPECT_GT(t.elapsed_s, testProgram()->cut_time_s);
    EXPECT_TRUE(t.homed);
    EXPECT_FALSE(t.torch_on);
    const CycleStats s = e.cycleStats();
    EXPECT_EQ(s.telemetry_dropped, 0u);
    EXPECT_EQ(samples, s.cycles) << "one sample per cycle";
}

TEST(Telemetry, LossIsCountedNotHidden) {
    SimCell cell;
    // Nobody drains: the ring (8192) overflows and the engine counts what it could not hand over.
    cell.engine().runCycles(10000, EngineState::Fault);
    const CycleStats s = cell.engine().cycleStats();
    std::uint64_t got = 0;
    TelemetrySample t;
    while (cell.engine().popTelemetry(t))
        ++got;
    EXPECT_GT(s.telemetry_dropped, 0u);
    EXPECT_EQ(got + s.telemetry_dropped, s.cycles);
}

TEST(Telemetry, RealTimeThreadDrainedAt30HzLosesNothing) {
    CellOptions o;
    o.clock = ClockMode::RealTime;
    SimCell cell(o);
    MotionEngine& e = cell.engine();
    e.enable();
    e.startThread();
    std::uint64_t got = 0;
    TelemetrySample t;
    for (int k = 0; k < 15; ++k) { // about half a second
        std::this_thread::sleep_for(std::chrono::milliseconds(33));
        while (e.popTelemetry(t))
            ++got;
    }
    e.stopThread();
    while (e.popTelemetry(t))
        ++got;
    const CycleStats s = e.cycleStats();
    EXPECT_EQ(s.telemetry_dropped, 0u);
    EXPECT_EQ(got, s.cycles);
    EXPECT_EQ(e.state(), EngineState::Ready);
}

// Object member (fails the test when absent).
const json::Value& at(const json::Value& v, const std::string& key) {
    const json::Value* m = v.find(key);
    if (!m) throw std::runtime_error("missing key " + key);
    return *m;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

TEST(RunLog, EachRunWritesJobEventsAndSummary) {
    const fs::path dir =
        fs::temp_directory_path() / ("cutcell_runlog_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    {
        CellOptions o;
        o.runs_dir = dir.string();
        SimCell cell(o);
        cell.toCompleted();
        cell.engine().flushRunLog();
        const fs::path run = cell.engine().lastRunDirectory();
        ASSERT_FALSE(run.empty());
        EXPECT_EQ(run.parent_path(), dir);
        // job.json: the job the run executed.
        const Job copy = parseJob(slurp(run / "job.json"));
        EXPECT_EQ(copy.name, testJob().name);
        EXPECT_EQ(copy.cut.speed_mm_s, testJob().cut.speed_mm_s);
        // events.log: the run's events, in order, one per line.
        const std::string log = slurp(run / "events.log");
        const auto started = log.find("Run 1 started");
        const auto arc = log.find("Arc established: cutting");
        const auto done = log.find("Completed: ");
        ASSERT_NE(started, std::string::npos) << log;
        ASSERT_NE(arc, std::string::npos) << log;
        ASSERT_NE(done, std::string::npos) << log;
        EXPECT_LT(started, arc);
        EXPECT_LT(arc, done);
        // summary.json: the engine's own figures.
        const json::Value summary = json::parse(slurp(run / "summary.json"));
        EXPECT_EQ(at(summary, "outcome").asString(), "completed");
        EXPECT_EQ(summary.find("stop"), nullptr); // a completed run did not stop short
        TrackingReport r;
        ASSERT_TRUE(cell.engine().lastRunReport(r));
        const json::Value& joints = at(at(summary, "tracking"), "joints");
        for (size_t i = 0; i < kAxisCount; ++i)
            EXPECT_NEAR(at(joints.asArray()[i], "max_abs_error_deg").asNumber(),
                        r.joints[i].max_abs,
                        1e-12 * r.joints[i].max_abs); // as written by the JSON writer
        // Events outside a run go to the runs folder's engine.log.
        EXPECT_NE(slurp(dir / "engine.log").find("Drives enabled"), std::string::npos);
    }
    fs::remove_all(dir);
}

// Why the program ended belongs to the run it ended, even when another event came after the
// run's end and opened engine.log (CI, canopen_cli under load: the SIGTERM line was missing
// from the run's events.log).
TEST(RunLog, TheLastRunsLineGoesToItsRunAfterLaterEvents) {
    const fs::path dir =
        fs::temp_directory_path() / ("cutcell_runlog_last_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    {
        RunLog log(dir.string());
        const auto event = [](const char* text) {
            EngineEvent e;
            std::snprintf(e.text.data(), e.text.size(), "%s", text);
            return e;
        };
        log.beginRun(1, "job", "{}");
        const fs::path run = log.runDirectory();
        log.event(event("inside the run"));
        log.endRun("emergency stop", TrackingReport{}, CycleStats{});
        log.event(event("after the run"));
        log.eventForLastRun(event("program ending (SIGTERM)"));
        const std::string runLog = slurp(run / "events.log");
        EXPECT_NE(runLog.find("inside the run"), std::string::npos) << runLog;
        EXPECT_NE(runLog.find("program ending (SIGTERM)"), std::string::npos) << runLog;
        EXPECT_EQ(runLog.find("after the run"), std::string::npos) << runLog;
        const std::string engineLog = slurp(dir / "engine.log");
        EXPECT_NE(engineLog.find("after the run"), std::string::npos) << engineLog;
        EXPECT_EQ(engineLog.find("program ending"), std::string::npos) << engineLog;
    }
    fs::remove_all(dir);
}

TEST(RunLog, AFaultedRunStillHasItsSummary) {
    const fs::path dir =
        fs::temp_directory_path() / ("cutcell_runlog_f_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    {
        CellOptions o;
        o.runs_dir = dir.string();
        SimCell cell(o);
        cell.toCutting(1.0);
        cell.drive(1).injectFault(0x2310);
        cell.runUntil(EngineState::Fault);
        cell.engine().flushRunLog();
        const fs::path run = cell.engine().lastRunDirectory();
        const json::Value summary = json::parse(slurp(run / "summary.json"));
        EXPECT_NE(at(summary, "outcome").asString().find("axis 1 (theta1): drive fault 0x2310"),
                  std::string::npos);
        EXPECT_NE(slurp(run / "events.log").find("Fault: axis 1"), std::string::npos);
        // Where it stopped: about 1 s into the path (the fault comes within a few cycles of
        // the injection), its length and point consistent with the program's.
        const json::Value& stop = at(summary, "stop");
        const double t = at(stop, "path_time_s").asNumber();
        EXPECT_GE(t, 1.0 - 1e-9);
        EXPECT_LT(t, 1.0 + 0.05);
        const double cutTime = at(at(summary, "tracking"), "cut_time_s").asNumber();
        EXPECT_NEAR(at(stop, "progress").asNumber(), t / cutTime, 1e-12);
        EXPECT_NEAR(at(stop, "length_mm").asNumber(),
                    at(stop, "progress").asNumber() *
                        at(at(summary, "tracking"), "length_mm").asNumber(),
                    1e-9);
        EXPECT_GT(at(stop, "elapsed_s").asNumber(), t); // the approach came first
        EXPECT_LE(at(stop, "point_index").asNumber(), at(stop, "point_count").asNumber());
    }
    fs::remove_all(dir);
}

// A runs folder that cannot be created (here: its parent is a file) is said once on stderr
// and as a Warning event (the GUI's event log, the CLI's event lines), never silently.
TEST(RunLog, AFolderThatCannotBeCreatedIsAWarning) {
    const fs::path blocker =
        fs::temp_directory_path() / ("cutcell_runlog_file_" + std::to_string(::getpid()));
    std::ofstream(blocker) << "not a folder";
    const std::string runs = (blocker / "runs").string();
    {
        CellOptions o;
        o.runs_dir = runs;
        SimCell cell(o);
        cell.toReady(true);
        testing::internal::CaptureStderr();
        cell.engine().flushRunLog();
        cell.cycleOnce(); // the engine thread reports what the logger found
        cell.engine().flushRunLog();
        const std::string err = testing::internal::GetCapturedStderr();
        const std::string said = "warning: run log: cannot create " + runs;
        EXPECT_NE(err.find(said), std::string::npos) << err;
        EXPECT_EQ(err.find(said), err.rfind(said)) << "said once, not once per event: " << err;
        int warnings = 0;
        for (const EngineEvent& e : cell.events)
            if (e.severity == Severity::Warning &&
                std::string(e.text.data()).find("Run log: cannot create " + runs) == 0)
                ++warnings;
        EXPECT_EQ(warnings, 1) << cell.eventText();
    }
    fs::remove(blocker);
}

} // namespace
} // namespace cutcell::test
