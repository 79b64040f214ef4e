#pragma once
// The production record's runs: one row per run - machine, job name, the job file and its
// fingerprint, operator, start and end, outcome, cycle time, what was made and where a short
// run stopped (summary.json's "made" and "stop") - and its alarms. Kept in a SQLite file (the
// user's data folder by default) or on a PostgreSQL server (a connection string), the same
// tables and statements in both (record_db.h). A run left open by a killed
// program (its host's process is gone) is closed as "interrupted" when the record is next
// opened; a run of a program still running stays open.
//
// The run log calls it on the engine's logger thread (RunRecordSink); queries may come from any
// thread: one connection behind a mutex.
#include "core/record/run_record.h"
#include "devices/record/record_db.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace cutcell {

// The host a program runs on, as the record names it: its name and its machine id's first 12
// hex digits (cells cloned from one image share a name, never a machine id; a shared server's
// record tells them apart).
std::string recordHostName();

class RunRecordStore final : public RunRecordSink, public RunHistory {
  public:
    static constexpr int kSchemaVersion = kProductionDbSchema;

    // Opens or creates the record `where` (a file, its folder too; or a server's database) and
    // migrates it; throws RecordError naming it and the database's reason.
    RunRecordStore(const std::string& where, std::string operatorName);
    ~RunRecordStore() override;
    RunRecordStore(const RunRecordStore&) = delete;
    RunRecordStore& operator=(const RunRecordStore&) = delete;

    // Runs found open at the start whose program was killed, now closed as "interrupted".
    int interruptedAtOpen() const { return interrupted_; }
    // The file, or the server and database (no password).
    const std::string& where() const { return db_->where(); }
    int schemaVersion() const;

    // Who the next runs are by (the logged-in user); "" keeps the desktop's user.
    void setOperator(const std::string& name);

    void opened(const RunOpening& run) override;
    void alarm(const RunAlarmNote& alarm) override;
    void closed(const RunClosing& run) override;

    std::vector<RecordedRun> runs(const RunQuery& query) const override; // oldest first
    std::vector<RunAlarmNote> alarmsOf(std::int64_t runId) const override;
    std::string jobTextOf(std::int64_t runId) const override;
    // "ok" for a sound record (SQLite: PRAGMA integrity_check; PostgreSQL: PgRecordDb's).
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
    std::string operator_;         // [mutex_]
    std::string desktopOperator_;  // the one given at the start
    std::unique_ptr<RecordDb> db_; // [mutex_]
    mutable std::mutex mutex_;
    std::int64_t openRun_ = 0; // row of the run being recorded
    int interrupted_ = 0;
};

} // namespace cutcell
