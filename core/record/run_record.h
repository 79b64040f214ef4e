#pragma once
// The production record as core sees it: one sink told when a run opens, what alarms it raises
// and how it closes, in the run log's own words (the job file, summary.json). The run log
// (core/engine/run_log.h) calls it on the engine's logger thread, never in the cycle; a sink
// may do I/O and take its time. devices/record/ keeps the record in SQLite; the app wires it.
#include <cstdint>
#include <string>
#include <vector>

namespace cutcell {

struct RunOpening {
    std::uint32_t engine_run_id = 0; // the engine's run number (restarts with the program)
    std::string job_name;
    std::string job_text; // the job file the run executes
    std::string run_dir;  // its run-log folder ("" when none is written)
    std::int64_t unix_ms = 0;
};

struct RunAlarmNote {
    std::int64_t unix_ms = 0;
    std::string severity; // "warning", "error", "fault"
    std::string text;
};

struct RunClosing {
    std::string outcome; // "completed", "aborted", "emergency stop", "fault: ..."
    std::int64_t unix_ms = 0;
    std::string summary_json; // the run's summary.json: figures, stop point, what was made
};

// One cut of a run ended: its tool went off (pierce to arc off), however the cut ended.
struct RunCutNote {
    std::int64_t unix_ms = 0;
    double tool_on_s = 0; // this cut's arc-on (tool-on) time
    double length_mm = 0; // the path it covered (0 for a program without a path length)
};

class RunRecordSink {
  public:
    virtual ~RunRecordSink() = default;
    virtual void opened(const RunOpening& run) = 0;
    virtual void alarm(const RunAlarmNote& alarm) = 0;
    // Told at each cut's end, while the run is open (consumable statistics count it then, so a
    // program killed mid-run loses only the cut under way). Ignored by default.
    virtual void cutEnded(const RunCutNote& /*cut*/) {}
    virtual void closed(const RunClosing& run) = 0;
};

struct RecordedRun {
    std::int64_t id = 0;
    std::string machine, job_name, job_hash, operator_name, run_dir;
    std::string outcome; // "" while running; "interrupted" if the program died
    std::int64_t started_ms = 0, ended_ms = 0; // ms since the epoch; ended 0 while open
    double cycle_time_s = 0;
    std::string made_json, stop_json; // "" when the run's summary had none
    int alarms = 0;
};

struct RunQuery {
    std::int64_t since_ms = 0; // runs started at or after this
    std::string machine;       // "" for every machine
    std::string outcome;       // "" for every outcome
};

// The record read back (the History view, `cutcell-cli history`): devices/record/ answers.
class RunHistory {
  public:
    virtual ~RunHistory() = default;
    virtual std::vector<RecordedRun> runs(const RunQuery& query) const = 0; // oldest first
    virtual std::vector<RunAlarmNote> alarmsOf(std::int64_t runId) const = 0;
    virtual std::string jobTextOf(std::int64_t runId) const = 0;
};

} // namespace cutcell
