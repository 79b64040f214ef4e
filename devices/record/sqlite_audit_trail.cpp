#include "devices/record/sqlite_audit_trail.h"

#include "core/job/job_io.h"
#include "core/json/json.h"

#include <algorithm>
#include <filesystem>

namespace cutcell {
namespace {

std::int64_t countRows(sqlite3* db) {
    Statement st(db, "SELECT count(*) FROM audit");
    return st.step() ? st.integer(0) : 0;
}

void insert(sqlite3* db, const AuditEvent& e) {
    Statement st(db, "INSERT INTO audit (time_ms, actor, event, key, old_value, new_value, unit, "
                     "detail) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)");
    st.bind(1, e.unix_ms > 0 ? e.unix_ms : unixMsNow())
        .bind(2, e.actor)
        .bind(3, e.event)
        .bind(4, e.key)
        .bind(5, e.old_value)
        .bind(6, e.new_value)
        .bind(7, e.unit)
        .bind(8, e.detail);
    st.step();
}

} // namespace

SqliteAuditTrail::SqliteAuditTrail(const std::string& path, std::int64_t maxRecords)
    : path_(path), maxRecords_(std::max<std::int64_t>(10, maxRecords)),
      db_(openProductionDb(path)) {}

SqliteAuditTrail::~SqliteAuditTrail() = default;

void SqliteAuditTrail::append(const AuditEvent& event) {
    std::lock_guard<std::mutex> lock(mutex_);
    insert(db_.get(), event);
    // Counted once, then kept (other writers' rows are found at the next roll's count): a
    // full count per event would scan the table each time.
    rows_ = rows_ < 0 ? countRows(db_.get()) : rows_ + 1;
    if (rows_ > maxRecords_ && rows_ >= rollRetryAt_) rollIfFull();
}

// Past the bound the oldest tenth goes to an archive file first, then leaves the table in one
// transaction (the delete trigger lets it through only while audit_state.archiving is set). A
// crash between the two leaves the records in both places, never in neither.
void SqliteAuditTrail::rollIfFull() {
    sqlite3* db = db_.get();
    const std::int64_t rows = rows_ = countRows(db);
    if (rows <= maxRecords_) return;
    const std::int64_t roll = rows - (maxRecords_ - maxRecords_ / 10);
    std::string lines;
    std::int64_t first = 0, last = 0;
    {
        Statement st(db, "SELECT id, time_ms, actor, event, key, old_value, new_value, unit, "
                         "detail FROM audit ORDER BY id LIMIT ?1");
        st.bind(1, roll);
        while (st.step()) {
            const AuditEvent e{st.integer(1), st.text(2), st.text(3), st.text(4),
                               st.text(5),    st.text(6), st.text(7), st.text(8)};
            last = st.integer(0);
            if (first == 0) first = last;
            lines += json::write(toJson({last, e}), -1); // one line, ending in a line break
        }
    }
    namespace fs = std::filesystem;
    const fs::path file = fs::path(archiveDir()) / ("audit-" + std::to_string(first) + "-" +
                                                    std::to_string(last) + ".jsonl");
    try {
        fs::create_directories(archiveDir());
        writeFileAtomically(file.string(), lines);
    } catch (const std::exception& e) {
        // Tried again after another tenth of the bound, not at every event.
        rollRetryAt_ = rows + std::max<std::int64_t>(1, maxRecords_ / 10);
        throw RecordError("audit trail " + path_ + ": " + std::to_string(rows) +
                          " records exceed the bound of " + std::to_string(maxRecords_) +
                          " and the archive " + file.string() +
                          " cannot be written (every record is kept): " + e.what());
    }
    execSql(db, "BEGIN IMMEDIATE;");
    try {
        execSql(db, "UPDATE audit_state SET archiving = 1;");
        Statement del(db, "DELETE FROM audit WHERE id <= ?1");
        del.bind(1, last).step();
        execSql(db, "UPDATE audit_state SET archiving = 0;");
        insert(db, {0, "cutcell", audit_event::kArchived, "", "", "", "",
                    std::to_string(roll) + " records (" + std::to_string(first) + " to " +
                        std::to_string(last) + ") moved to " + file.string()});
        execSql(db, "COMMIT;");
        rows_ = countRows(db);
    } catch (const RecordError&) {
        if (!sqlite3_get_autocommit(db)) sqlite3_exec(db, "ROLLBACK;", nullptr, nullptr, nullptr);
        throw;
    }
}

std::vector<RecordedAuditEvent> SqliteAuditTrail::events(std::int64_t sinceMs) const {
    std::lock_guard<std::mutex> lock(mutex_);
    Statement st(db_.get(), "SELECT id, time_ms, actor, event, key, old_value, new_value, unit, "
                            "detail FROM audit WHERE time_ms >= ?1 ORDER BY id");
    st.bind(1, sinceMs);
    std::vector<RecordedAuditEvent> out;
    while (st.step())
        out.push_back({st.integer(0),
                       {st.integer(1), st.text(2), st.text(3), st.text(4), st.text(5), st.text(6),
                        st.text(7), st.text(8)}});
    return out;
}

json::Value SqliteAuditTrail::toJson(const RecordedAuditEvent& r) {
    const AuditEvent& e = r.event;
    return json::Object{{"id", static_cast<double>(r.id)},
                        {"time_ms", static_cast<double>(e.unix_ms)},
                        {"actor", e.actor},
                        {"event", e.event},
                        {"key", e.key},
                        {"old", e.old_value},
                        {"new", e.new_value},
                        {"unit", e.unit},
                        {"detail", e.detail}};
}

std::int64_t SqliteAuditTrail::count() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return countRows(db_.get());
}

} // namespace cutcell
