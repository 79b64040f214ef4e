#include "devices/record/production_db.h"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iterator>

namespace cutcell {
namespace {

namespace fs = std::filesystem;

// Migration k takes the schema from version k to k + 1; never edited once shipped
// (tests/data/record/ keeps a file of each earlier schema).
const char* const kMigrations[] = {
    // 0 -> 1: runs and their alarms.
    "CREATE TABLE runs ("
    " id INTEGER PRIMARY KEY,"
    " engine_run_id INTEGER NOT NULL,"
    " machine TEXT NOT NULL,"
    " job_name TEXT NOT NULL,"
    " job_hash TEXT NOT NULL,"
    " job_text TEXT NOT NULL,"
    " operator TEXT NOT NULL,"
    " run_dir TEXT NOT NULL,"
    " host TEXT NOT NULL,"
    " pid INTEGER NOT NULL,"
    " started_ms INTEGER NOT NULL,"
    " ended_ms INTEGER,"
    " outcome TEXT,"
    " cycle_time_s REAL,"
    " made_json TEXT,"
    " stop_json TEXT,"
    " summary_json TEXT);"
    "CREATE INDEX runs_started ON runs(started_ms);"
    "CREATE TABLE alarms ("
    " id INTEGER PRIMARY KEY,"
    " run_id INTEGER NOT NULL REFERENCES runs(id),"
    " time_ms INTEGER NOT NULL,"
    " severity TEXT NOT NULL,"
    " text TEXT NOT NULL);"
    "CREATE INDEX alarms_run ON alarms(run_id);",
    // 1 -> 2: the station's users (Argon2id hashes, lock-out) and the audit trail. The trail is
    // append-only in the file itself: no UPDATE ever, a DELETE only while records are rolled
    // into an archive file (audit_state.archiving, set by SqliteAuditTrail in that transaction).
    "CREATE TABLE users ("
    " name TEXT PRIMARY KEY,"
    " level TEXT NOT NULL CHECK (level IN ('operator', 'setter', 'engineer', 'administrator')),"
    " pwhash TEXT NOT NULL,"
    " created_ms INTEGER NOT NULL,"
    " failed_logins INTEGER NOT NULL DEFAULT 0,"
    " locked_until_ms INTEGER NOT NULL DEFAULT 0);"
    "CREATE TABLE audit ("
    " id INTEGER PRIMARY KEY,"
    " time_ms INTEGER NOT NULL,"
    " actor TEXT NOT NULL,"
    " event TEXT NOT NULL,"
    " key TEXT NOT NULL DEFAULT '',"
    " old_value TEXT NOT NULL DEFAULT '',"
    " new_value TEXT NOT NULL DEFAULT '',"
    " unit TEXT NOT NULL DEFAULT '',"
    " detail TEXT NOT NULL DEFAULT '');"
    "CREATE INDEX audit_time ON audit(time_ms);"
    "CREATE TABLE audit_state (archiving INTEGER NOT NULL);"
    "INSERT INTO audit_state VALUES (0);"
    "CREATE TRIGGER audit_no_update BEFORE UPDATE ON audit BEGIN"
    " SELECT RAISE(ABORT, 'the audit trail is append-only'); END;"
    "CREATE TRIGGER audit_no_delete BEFORE DELETE ON audit"
    " WHEN (SELECT archiving FROM audit_state) = 0 BEGIN"
    " SELECT RAISE(ABORT, 'the audit trail is append-only: records leave it only into an "
    "archive'); END;",
};
static_assert(std::size(kMigrations) == kProductionDbSchema);

void migrate(sqlite3* db) {
    int version = schemaVersionOf(db);
    if (version > kProductionDbSchema)
        throw RecordError("schema version " + std::to_string(version) +
                          " was written by a newer CutCell (this one knows up to " +
                          std::to_string(kProductionDbSchema) + ")");
    for (; version < kProductionDbSchema; ++version) {
        execSql(db, "BEGIN IMMEDIATE;");
        try {
            // Another connection may have migrated while this one waited for the lock.
            if (schemaVersionOf(db) != version) {
                execSql(db, "ROLLBACK;");
                version = schemaVersionOf(db) - 1;
                continue;
            }
            execSql(db, kMigrations[version]);
            execSql(db, ("PRAGMA user_version = " + std::to_string(version + 1) + ";").c_str());
            execSql(db, "COMMIT;");
        } catch (const RecordError&) {
            // SQLite may have rolled back already: a second error would hide the first.
            if (!sqlite3_get_autocommit(db))
                sqlite3_exec(db, "ROLLBACK;", nullptr, nullptr, nullptr);
            throw;
        }
    }
    if (const int now = schemaVersionOf(db); now > kProductionDbSchema) // migrated by another
        throw RecordError("schema version " + std::to_string(now) +
                          " was written by a newer CutCell (this one knows up to " +
                          std::to_string(kProductionDbSchema) + ")");
}

} // namespace

void execSql(sqlite3* db, const char* sql) {
    char* err = nullptr;
    if (sqlite3_exec(db, sql, nullptr, nullptr, &err) != SQLITE_OK) {
        const std::string why = err ? err : sqlite3_errmsg(db);
        sqlite3_free(err);
        throw RecordError(why);
    }
}

int schemaVersionOf(sqlite3* db) {
    Statement st(db, "PRAGMA user_version");
    return st.step() ? static_cast<int>(st.integer(0)) : 0;
}

SqliteHandle openProductionDb(const std::string& path) {
    std::error_code ec;
    if (const fs::path dir = fs::path(path).parent_path(); !dir.empty())
        fs::create_directories(dir, ec);
    sqlite3* raw = nullptr;
    const int rc =
        sqlite3_open_v2(path.c_str(), &raw, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
    SqliteHandle db(raw);
    if (rc != SQLITE_OK)
        throw RecordError("production record " + path + ": cannot open (" +
                          (raw ? sqlite3_errmsg(raw) : "out of memory") + ")");
    try {
        sqlite3_busy_timeout(db.get(), 5000);
        execSql(db.get(), "PRAGMA journal_mode=WAL;");
        execSql(db.get(), "PRAGMA foreign_keys=ON;");
        migrate(db.get());
    } catch (const RecordError& e) {
        throw RecordError("production record " + path + ": " + e.what());
    }
    return db;
}

std::string defaultProductionDbPath() {
    const char* xdg = std::getenv("XDG_DATA_HOME");
    fs::path base;
    if (xdg && *xdg)
        base = xdg;
    else if (const char* home = std::getenv("HOME"); home && *home)
        base = fs::path(home) / ".local" / "share";
    else
        base = ".";
    return (base / "cutcell" / "production.db").string();
}

std::int64_t unixMsNow() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}

} // namespace cutcell
