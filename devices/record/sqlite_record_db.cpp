#include "devices/record/sqlite_record_db.h"

#include <sqlite3.h>

#include <filesystem>

namespace cutcell {
namespace {

std::string newerSchema(int version) {
    return "schema version " + std::to_string(version) +
           " was written by a newer CutCell (this one knows up to " +
           std::to_string(kProductionDbSchema) + ")";
}

} // namespace

void SqliteRecordDb::Closer::operator()(sqlite3* db) const {
    sqlite3_close(db);
}

SqliteRecordDb::SqliteRecordDb(const std::string& path) : path_(path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (const fs::path dir = fs::path(path).parent_path(); !dir.empty())
        fs::create_directories(dir, ec);
    sqlite3* raw = nullptr;
    const int rc =
        sqlite3_open_v2(path.c_str(), &raw, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
    db_.reset(raw);
    if (rc != SQLITE_OK)
        throw RecordError("production record " + path + ": cannot open (" +
                          (raw ? sqlite3_errmsg(raw) : "out of memory") + ")");
    try {
        sqlite3_busy_timeout(db_.get(), 5000);
        exec("PRAGMA journal_mode=WAL;");
        exec("PRAGMA foreign_keys=ON;");
        migrate();
    } catch (const RecordError& e) {
        throw RecordError("production record " + path + ": " + e.what());
    }
}

SqliteRecordDb::~SqliteRecordDb() = default;

void SqliteRecordDb::exec(const char* sql) {
    char* err = nullptr;
    if (sqlite3_exec(db_.get(), sql, nullptr, nullptr, &err) != SQLITE_OK) {
        const std::string why = err ? err : sqlite3_errmsg(db_.get());
        sqlite3_free(err);
        throw RecordError(why);
    }
}

SqlRows SqliteRecordDb::query(const std::string& sql, const std::vector<SqlValue>& params) {
    sqlite3* db = db_.get();
    sqlite3_stmt* raw = nullptr;
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &raw, nullptr) != SQLITE_OK)
        throw RecordError("production record: " + std::string(sqlite3_errmsg(db)));
    const std::unique_ptr<sqlite3_stmt, int (*)(sqlite3_stmt*)> st(raw, sqlite3_finalize);
    for (std::size_t i = 0; i < params.size(); ++i) {
        const int n = static_cast<int>(i + 1);
        const SqlValue& v = params[i];
        if (const auto* x = std::get_if<std::int64_t>(&v))
            sqlite3_bind_int64(raw, n, *x);
        else if (const auto* d = std::get_if<double>(&v))
            sqlite3_bind_double(raw, n, *d);
        else if (const auto* s = std::get_if<std::string>(&v))
            sqlite3_bind_text(raw, n, s->data(), static_cast<int>(s->size()), SQLITE_TRANSIENT);
        else
            sqlite3_bind_null(raw, n);
    }
    SqlRows rows;
    for (;;) {
        const int rc = sqlite3_step(raw);
        if (rc == SQLITE_DONE) break;
        if (rc != SQLITE_ROW)
            throw RecordError("production record: " + std::string(sqlite3_errmsg(db)));
        const int n = sqlite3_column_count(raw);
        std::vector<SqlValue> cells;
        cells.reserve(static_cast<std::size_t>(n));
        for (int c = 0; c < n; ++c) {
            switch (sqlite3_column_type(raw, c)) {
            case SQLITE_INTEGER:
                cells.emplace_back(sqlite3_column_int64(raw, c));
                break;
            case SQLITE_FLOAT:
                cells.emplace_back(sqlite3_column_double(raw, c));
                break;
            case SQLITE_NULL:
                cells.emplace_back(std::monostate{});
                break;
            default: {
                const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(raw, c));
                cells.emplace_back(std::string(
                    p ? p : "", static_cast<std::size_t>(sqlite3_column_bytes(raw, c))));
            }
            }
        }
        rows.emplace_back(std::move(cells));
    }
    return rows;
}

void SqliteRecordDb::begin() {
    exec("BEGIN IMMEDIATE;");
}

void SqliteRecordDb::commit() {
    exec("COMMIT;");
}

void SqliteRecordDb::rollback() noexcept {
    // SQLite may have rolled back already (after some errors): a second error would hide the
    // first.
    if (!sqlite3_get_autocommit(db_.get()))
        sqlite3_exec(db_.get(), "ROLLBACK;", nullptr, nullptr, nullptr);
}

int SqliteRecordDb::schemaVersion() {
    const SqlRows r = query("PRAGMA user_version");
    return r.empty() ? 0 : static_cast<int>(r[0].integer(0));
}

std::string SqliteRecordDb::integrityCheck() {
    const SqlRows r = query("PRAGMA integrity_check");
    std::string out;
    for (const SqlRow& row : r)
        out += (out.empty() ? "" : "; ") + row.text(0);
    return out;
}

void SqliteRecordDb::migrate() {
    int version = schemaVersion();
    if (version > kProductionDbSchema) throw RecordError(newerSchema(version));
    for (; version < kProductionDbSchema; ++version) {
        begin();
        try {
            // Another connection may have migrated while this one waited for the lock.
            if (schemaVersion() != version) {
                rollback();
                version = schemaVersion() - 1;
                continue;
            }
            exec(migrationSql(version, SqlDialect::Sqlite).c_str());
            exec(("PRAGMA user_version = " + std::to_string(version + 1) + ";").c_str());
            commit();
        } catch (const RecordError&) {
            rollback();
            throw;
        }
    }
    if (const int now = schemaVersion(); now > kProductionDbSchema) // migrated by another
        throw RecordError(newerSchema(now));
}

} // namespace cutcell
