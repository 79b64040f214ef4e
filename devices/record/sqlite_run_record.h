#pragma once
// The production record in SQLite (Debian libsqlite3): one row per run - machine, job name,
// the job file and its fingerprint, operator, start and end, outcome, cycle time, what was
// made and where a short run stopped (summary.json's "made" and "stop") - and its alarms. One
// file (the user's data folder by default), WAL journal, the schema versioned by
// PRAGMA user_version with migrations from every earlier version. A run left open by a killed
// program (its host's process is gone) is closed as "interrupted" when the record is next
// opened; a run of a program still running stays open.
//
// The run log calls it on the engine's logger thread (RunRecordSink); queries may come from any
// thread: one connection behind a mutex.
#include "core/record/run_record.h"
#include "devices/record/production_db.h"

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace cutcell {

class SqliteRunRecord final : public RunRecordSink, public RunHistory {
  public:
    static constexpr int kSchemaVersion = kProductionDbSchema;

    // Opens or creates the record at `path` (its folder too) and migrates it; throws
    // RecordError naming the file and SQLite's reason.
    SqliteRunRecord(const std::string& path, std::string operatorName);
    ~SqliteRunRecord() override;
    SqliteRunRecord(const SqliteRunRecord&) = delete;
    SqliteRunRecord& operator=(const SqliteRunRecord&) = delete;

    // Runs found open at the start whose program was killed, now closed as "interrupted".
    int interruptedAtOpen() const { return interrupted_; }
    const std::string& path() const { return path_; }
    int schemaVersion() const;

    // Who the next runs are by (the logged-in user); "" keeps the desktop's user.
    void setOperator(const std::string& name);

    void opened(const RunOpening& run) override;
    void alarm(const RunAlarmNote& alarm) override;
    void closed(const RunClosing& run) override;

    std::vector<RecordedRun> runs(const RunQuery& query) const override; // oldest first
    std::vector<RunAlarmNote> alarmsOf(std::int64_t runId) const override;
    std::string jobTextOf(std::int64_t runId) const override;
    // PRAGMA integrity_check's answer ("ok" for a sound file).
    std::string integrityCheck() const;

    // Who is at the station: the desktop's user ($USER, $LOGNAME) until user levels bring
    // logins; "unknown".
    static std::string desktopUser();
    // $XDG_DATA_HOME/cutcell/production.db, or ~/.local/share/cutcell/production.db.
    static std::string defaultPath();
    // The machine a job file is for (its machine.kind, or a schema-1 job's machine); "".
    static std::string machineOfJob(const std::string& jobText);
    // A fingerprint of the job file (FNV-1a 64, hex): tells equal jobs apart, not a signature.
    static std::string jobFingerprint(const std::string& jobText);

  private:
    void closeInterrupted();
    std::string path_;
    std::string operator_;        // [mutex_]
    std::string desktopOperator_; // the one given at the start
    SqliteHandle db_;
    mutable std::mutex mutex_;
    std::int64_t openRun_ = 0; // row of the run being recorded
    int interrupted_ = 0;
};

} // namespace cutcell
