#include "devices/record/run_record_store.h"

#include "core/json/json.h"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace cutcell {
namespace {

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

std::string recordHostName() {
    char name[256] = {};
    std::string host = gethostname(name, sizeof name - 1) == 0 ? name : "unknown";
    std::ifstream id("/etc/machine-id");
    std::string machineId;
    if (std::getline(id, machineId) && machineId.size() >= 12)
        host += " (" + machineId.substr(0, 12) + ")";
    return host;
}

RunRecordStore::RunRecordStore(const std::string& where, std::string operatorName)
    : operator_(std::move(operatorName)), desktopOperator_(operator_), db_(openRecordDb(where)) {
    try {
        closeInterrupted();
    } catch (const RecordError& e) {
        throw RecordError("production record " + db_->where() + ": " + e.what());
    }
}

RunRecordStore::~RunRecordStore() = default;

// A run still open whose program (this host's) is gone was killed: closed as "interrupted".
// Runs of a program still running (the GUI while a CLI reads) stay open; another host's
// runs are that host's to close.
void RunRecordStore::closeInterrupted() {
    std::vector<std::int64_t> dead;
    for (const SqlRow& open : db_->query(
             "SELECT id, pid FROM runs WHERE ended_ms IS NULL AND host = ?1", {recordHostName()}))
        if (!processAlive(open.integer(1))) dead.push_back(open.integer(0));
    for (const std::int64_t id : dead)
        db_->query("UPDATE runs SET outcome = 'interrupted', ended_ms = ?2, "
                   "cycle_time_s = (?2 - started_ms) / 1000.0 WHERE id = ?1 AND ended_ms IS NULL",
                   {id, unixMsNow()});
    interrupted_ = static_cast<int>(dead.size());
}

int RunRecordStore::schemaVersion() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return db_->schemaVersion();
}

void RunRecordStore::setOperator(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    operator_ = name.empty() ? desktopOperator_ : name;
}

void RunRecordStore::opened(const RunOpening& run) {
    std::lock_guard<std::mutex> lock(mutex_);
    const SqlRows id = db_->query(
        "INSERT INTO runs (engine_run_id, machine, job_name, job_hash, job_text, "
        "operator, run_dir, host, pid, started_ms) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, "
        "?10) RETURNING id",
        {static_cast<std::int64_t>(run.engine_run_id), machineOfJob(run.job_text), run.job_name,
         jobFingerprint(run.job_text), run.job_text, operator_, run.run_dir, recordHostName(),
         static_cast<std::int64_t>(getpid()), run.unix_ms});
    openRun_ = id.empty() ? 0 : id[0].integer(0);
}

void RunRecordStore::alarm(const RunAlarmNote& alarm) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (openRun_ == 0) return;
    db_->query("INSERT INTO alarms (run_id, time_ms, severity, text) VALUES (?1, ?2, ?3, ?4)",
               {openRun_, alarm.unix_ms, alarm.severity, alarm.text});
}

void RunRecordStore::closed(const RunClosing& run) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (openRun_ == 0) return;
    // The cycle time on the engine's clock (summary.json's elapsed_s; a fast-clock run takes
    // less wall time), the wall clock's if the summary has none.
    SqlValue elapsed;
    if (const std::string e = summaryMember(run.summary_json, "elapsed_s"); !e.empty()) {
        double v = 0;
        if (std::from_chars(e.data(), e.data() + e.size(), v).ec == std::errc() && std::isfinite(v))
            elapsed = v;
    }
    db_->query("UPDATE runs SET ended_ms = ?2, outcome = ?3, cycle_time_s = "
               "coalesce(?7, (?2 - started_ms) / 1000.0), made_json = ?4, stop_json = ?5, "
               "summary_json = ?6 WHERE id = ?1",
               {openRun_, run.unix_ms, run.outcome, summaryMember(run.summary_json, "made"),
                summaryMember(run.summary_json, "stop"), run.summary_json, elapsed});
    openRun_ = 0;
}

std::vector<RecordedRun> RunRecordStore::runs(const RunQuery& q) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const SqlRows rows =
        db_->query("SELECT id, machine, job_name, job_hash, operator, run_dir, "
                   "coalesce(outcome, ''), started_ms, coalesce(ended_ms, 0), "
                   "coalesce(cycle_time_s, 0), coalesce(made_json, ''), "
                   "coalesce(stop_json, ''), "
                   "(SELECT count(*) FROM alarms WHERE alarms.run_id = runs.id) "
                   "FROM runs WHERE started_ms >= ?1 AND (?2 = '' OR machine = ?2) "
                   "AND (?3 = '' OR coalesce(outcome, '') = ?3) ORDER BY started_ms, id",
                   {q.since_ms, q.machine, q.outcome});
    std::vector<RecordedRun> out;
    out.reserve(rows.size());
    for (const SqlRow& row : rows) {
        RecordedRun r;
        r.id = row.integer(0);
        r.machine = row.text(1);
        r.job_name = row.text(2);
        r.job_hash = row.text(3);
        r.operator_name = row.text(4);
        r.run_dir = row.text(5);
        r.outcome = row.text(6);
        r.started_ms = row.integer(7);
        r.ended_ms = row.integer(8);
        r.cycle_time_s = row.real(9);
        r.made_json = row.text(10);
        r.stop_json = row.text(11);
        r.alarms = static_cast<int>(row.integer(12));
        out.push_back(std::move(r));
    }
    return out;
}

std::vector<RunAlarmNote> RunRecordStore::alarmsOf(std::int64_t runId) const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<RunAlarmNote> out;
    for (const SqlRow& row : db_->query(
             "SELECT time_ms, severity, text FROM alarms WHERE run_id = ?1 ORDER BY id", {runId}))
        out.push_back({row.integer(0), row.text(1), row.text(2)});
    return out;
}

std::string RunRecordStore::jobTextOf(std::int64_t runId) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const SqlRows r = db_->query("SELECT job_text FROM runs WHERE id = ?1", {runId});
    return r.empty() ? std::string() : r[0].text(0);
}

std::string RunRecordStore::integrityCheck() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return db_->integrityCheck();
}

std::string RunRecordStore::desktopUser() {
    for (const char* var : {"USER", "LOGNAME"})
        if (const char* v = std::getenv(var); v && *v) return v;
    return "unknown";
}

std::string RunRecordStore::defaultPath() {
    return defaultProductionDbPath();
}

std::string RunRecordStore::machineOfJob(const std::string& jobText) {
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

std::string RunRecordStore::jobFingerprint(const std::string& jobText) {
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
