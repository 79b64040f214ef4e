#pragma once
// The production record's SQLite file, shared by its tables: the runs and their alarms
// (SqliteRunRecord), the station's users (SqliteUserDirectory) and the audit trail
// (SqliteAuditTrail). Each opens its own connection through openProductionDb, which creates the
// file (and its folder), sets WAL and a busy timeout (the GUI and a CLI share the file) and
// migrates the schema (PRAGMA user_version) from any earlier version.
#include "devices/record/sqlite_statement.h"

#include <cstdint>
#include <memory>
#include <string>

namespace cutcell {

inline constexpr int kProductionDbSchema = 2;

struct SqliteCloser {
    void operator()(sqlite3* db) const { sqlite3_close(db); }
};
using SqliteHandle = std::unique_ptr<sqlite3, SqliteCloser>;

// Throws RecordError naming the file and SQLite's reason (a newer schema is refused).
SqliteHandle openProductionDb(const std::string& path);

void execSql(sqlite3* db, const char* sql); // throws RecordError
int schemaVersionOf(sqlite3* db);

// $XDG_DATA_HOME/cutcell/production.db, or ~/.local/share/cutcell/production.db.
std::string defaultProductionDbPath();
std::int64_t unixMsNow();

} // namespace cutcell
