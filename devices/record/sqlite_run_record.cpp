#include "devices/record/sqlite_run_record.h"

#include "core/json/json.h"

#include <sqlite3.h>

#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>

namespace cutcell {
namespace {

std::string hostName() {
    char name[256] = {};
    if (gethostname(name, sizeof name - 1) != 0) return "unknown";
    return name;
}

// Whether a process of this host still runs (kill(pid, 0) fails with ESRCH once it is gone).
bool processAlive(std::int64_t pid) {
    return pid > 0 && (kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
}

// A member of the summary's JSON as text ("" when absent or the summary is not JSON).
std::string summaryMember(const std::string& summary, const char* key) {
    try {
        const json::Value doc = json::parse(summary);
        if (const json::Value* v = doc.find(key)) return json::write(*v, 0);
    } catch (const std::exception&) {
    }
    return {};
}

} // namespace

SqliteRunRecord::SqliteRunRecord(const std::string& path, std::string operatorName)
    : path_(path), operator_(std::move(operatorName)), desktopOperator_(operator_),
      db_(openProductionDb(path)) {
    try {
        closeInterrupted();
    } catch (const RecordError& e) {
        throw RecordError("production record " + path + ": " + e.what());
    }
}

SqliteRunRecord::~SqliteRunRecord() = default;

// A run still open whose program (this host's) is gone was killed: closed as "interrupted".
// Runs of a program still running (the GUI while a CLI reads) stay open; another host's
// runs are that host's to close.
void SqliteRunRecord::closeInterrupted() {
    std::vector<std::int64_t> dead;
    {
        Statement open(db_.get(), "SELECT id, pid FROM runs WHERE ended_ms IS NULL AND host = ?1");
        open.bind(1, hostName());
        while (open.step())
            if (!processAlive(open.integer(1))) dead.push_back(open.integer(0));
    }
    for (const std::int64_t id : dead) {
        Statement close(db_.get(), "UPDATE runs SET outcome = 'interrupted', ended_ms = ?2, "
                                   "cycle_time_s = (?2 - started_ms) / 1000.0 WHERE id = ?1");
        close.bind(1, id).bind(2, unixMsNow()).step();
    }
    interrupted_ = static_cast<int>(dead.size());
}

int SqliteRunRecord::schemaVersion() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return schemaVersionOf(db_.get());
}

void SqliteRunRecord::setOperator(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    operator_ = name.empty() ? desktopOperator_ : name;
}

void SqliteRunRecord::opened(const RunOpening& run) {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement st(
        db_.get(),
        "INSERT INTO runs (engine_run_id, machine, job_name, job_hash, job_text, "
        "operator, run_dir, host, pid, started_ms) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, "
        "?10)");
    st.bind(1, static_cast<std::int64_t>(run.engine_run_id))
        .bind(2, machineOfJob(run.job_text))
        .bind(3, run.job_name)
        .bind(4, jobFingerprint(run.job_text))
        .bind(5, run.job_text)
        .bind(6, operator_)
        .bind(7, run.run_dir)
        .bind(8, hostName())
        .bind(9, static_cast<std::int64_t>(getpid()))
        .bind(10, run.unix_ms);
    st.step();
    openRun_ = sqlite3_last_insert_rowid(db_.get());
}

void SqliteRunRecord::alarm(const RunAlarmNote& alarm) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (openRun_ == 0) return;
    Statement st(db_.get(),
                 "INSERT INTO alarms (run_id, time_ms, severity, text) VALUES (?1, ?2, ?3, ?4)");
    st.bind(1, openRun_).bind(2, alarm.unix_ms).bind(3, alarm.severity).bind(4, alarm.text);
    st.step();
}

void SqliteRunRecord::closed(const RunClosing& run) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (openRun_ == 0) return;
    // The cycle time on the engine's clock (summary.json's elapsed_s; a fast-clock run takes
    // less wall time), the wall clock's if the summary has none.
    const std::string elapsed = summaryMember(run.summary_json, "elapsed_s");
    Statement st(db_.get(),
                 "UPDATE runs SET ended_ms = ?2, outcome = ?3, cycle_time_s = "
                 "coalesce(?7, (?2 - started_ms) / 1000.0), made_json = ?4, stop_json = ?5, "
                 "summary_json = ?6 WHERE id = ?1");
    st.bind(1, openRun_)
        .bind(2, run.unix_ms)
        .bind(3, run.outcome)
        .bind(4, summaryMember(run.summary_json, "made"))
        .bind(5, summaryMember(run.summary_json, "stop"))
        .bind(6, run.summary_json);
    if (!elapsed.empty()) st.bind(7, std::strtod(elapsed.c_str(), nullptr));
    st.step();
    openRun_ = 0;
}

std::vector<RecordedRun> SqliteRunRecord::runs(const RunQuery& q) const {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement st(db_.get(), "SELECT id, machine, job_name, job_hash, operator, run_dir, "
                            "coalesce(outcome, ''), started_ms, coalesce(ended_ms, 0), "
                            "coalesce(cycle_time_s, 0), coalesce(made_json, ''), "
                            "coalesce(stop_json, ''), "
                            "(SELECT count(*) FROM alarms WHERE alarms.run_id = runs.id) "
                            "FROM runs WHERE started_ms >= ?1 AND (?2 = '' OR machine = ?2) "
                            "AND (?3 = '' OR coalesce(outcome, '') = ?3) ORDER BY started_ms, id");
    st.bind(1, q.since_ms).bind(2, q.machine).bind(3, q.outcome);
    std::vector<RecordedRun> out;
    while (st.step()) {
        RecordedRun r;
        r.id = st.integer(0);
        r.machine = st.text(1);
        r.job_name = st.text(2);
        r.job_hash = st.text(3);
        r.operator_name = st.text(4);
        r.run_dir = st.text(5);
        r.outcome = st.text(6);
        r.started_ms = st.integer(7);
        r.ended_ms = st.integer(8);
        r.cycle_time_s = st.real(9);
        r.made_json = st.text(10);
        r.stop_json = st.text(11);
        r.alarms = static_cast<int>(st.integer(12));
        out.push_back(std::move(r));
    }
    return out;
}

std::vector<RunAlarmNote> SqliteRunRecord::alarmsOf(std::int64_t runId) const {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement st(db_.get(),
                 "SELECT time_ms, severity, text FROM alarms WHERE run_id = ?1 ORDER BY id");
    st.bind(1, runId);
    std::vector<RunAlarmNote> out;
    while (st.step())
        out.push_back({st.integer(0), st.text(1), st.text(2)});
    return out;
}

std::string SqliteRunRecord::jobTextOf(std::int64_t runId) const {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement st(db_.get(), "SELECT job_text FROM runs WHERE id = ?1");
    st.bind(1, runId);
    return st.step() ? st.text(0) : std::string();
}

std::string SqliteRunRecord::integrityCheck() const {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement st(db_.get(), "PRAGMA integrity_check");
    return st.step() ? st.text(0) : std::string();
}

std::string SqliteRunRecord::desktopUser() {
    for (const char* var : {"USER", "LOGNAME"})
        if (const char* v = std::getenv(var); v && *v) return v;
    return "unknown";
}

std::string SqliteRunRecord::defaultPath() {
    return defaultProductionDbPath();
}

std::string SqliteRunRecord::machineOfJob(const std::string& jobText) {
    try {
        const json::Value doc = json::parse(jobText);
        const json::Value* m = doc.find("machine");
        if (!m) return {};
        if (m->isString()) return m->asString(); // schema 1
        if (const json::Value* kind = m->find("kind"); kind && kind->isString())
            return kind->asString();
    } catch (const std::exception&) {
    }
    return {};
}

std::string SqliteRunRecord::jobFingerprint(const std::string& jobText) {
    std::uint64_t h = 1469598103934665603ull;
    for (const unsigned char c : jobText) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

} // namespace cutcell
