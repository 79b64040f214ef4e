#pragma once
// The log of one engine run, under a runs directory:
//   <runs_dir>/<UTC yyyymmdd-hhmmss>-run<N>/job.json      copy of the job the run executed
//                                           events.log    one line per event, flushed per line
//                                           summary.json  outcome, tracking figures, cycle figures
// Threading contract: used by one non-cycle thread (the engine's logger thread, or the
// caller of MotionEngine::flushRunLog()); it does file I/O and may allocate.
#include "core/engine/engine_types.h"
#include "core/engine/run_terms.h"
#include "core/json/json.h"
#include "core/record/run_record.h"
#include "core/sim/tracking_stats.h"

#include <array>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace cutcell {

class RunLog {
  public:
    explicit RunLog(std::string runsDir) : runsDir_(std::move(runsDir)) {}
    ~RunLog();
    RunLog(const RunLog&) = delete;
    RunLog& operator=(const RunLog&) = delete;

    // The production record told of every run, its alarms and its end (null: none). Its
    // failures are reported like the log's own (takeProblem), never thrown.
    void setRecordSink(RunRecordSink* sink) { sink_ = sink; }
    // Opens a new run folder; events before the first run go to <runs_dir>/engine.log.
    void beginRun(std::uint32_t runId, const std::string& jobName, const std::string& jobText);
    // The names of the run's axes for summary.json (set after beginRun).
    void setAxisNames(const std::array<std::string, kMaxAxes>& names) { names_ = names; }
    // How the run's program counts its work, for summary.json's "made" (set after beginRun).
    void setTerms(const RunTerms& terms) { terms_ = terms; }
    void event(const EngineEvent& e);
    // An event about the current run, or, when none is open, the last one (e.g. why the program
    // ended right after a run stopped): appended to that run's events.log.
    void eventForLastRun(const EngineEvent& e);
    // Writes summary.json (atomically) and closes the run.
    void endRun(const std::string& outcome, const TrackingReport& report, const CycleStats& cycle,
                const RunStopPoint& stop = {}, const RunStopPoint& start = {},
                const RunStopPoint& end = {});
    // What a run made up to `end`, in the terms' words: summary.json's "made".
    static json::Value madeToJson(const RunTerms& terms, const RunStopPoint& end);
    std::string runDirectory() const { return dir_; }
    // A folder or file that could not be created since the last call ("" if none). Each new
    // problem is also printed once to stderr, so a run that is not logged never goes unnoticed.
    std::string takeProblem() { return std::exchange(problem_, {}); }
    // One event as a log line (also used by the CLI to print events).
    static std::string formatEvent(const EngineEvent& e);

  private:
    void beginRunFolder(std::uint32_t runId, const std::string& jobText);
    void openFile(const std::string& path);
    void problem(const std::string& what);
    template <class F> void tellRecord(F&& call);
    std::string runsDir_;
    std::string problem_;
    std::vector<std::string> reported_;
    std::string dir_;
    std::FILE* file_ = nullptr; // the run's events.log, or engine.log between runs
    bool runOpen_ = false;      // file_ is the open run's events.log
    RunRecordSink* sink_ = nullptr;
    bool recordOpen_ = false; // the sink was told of a run that has not closed
    std::array<std::string, kMaxAxes> names_{};
    RunTerms terms_;
};

} // namespace cutcell
