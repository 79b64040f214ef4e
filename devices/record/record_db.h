#pragma once
// One connection to the production record, whichever database keeps it: a SQLite file (the
// default, one file in the user's data folder) or a PostgreSQL server shared by a shop's cells
// (selected by a connection string). The record's tables (runs and alarms, users, the audit
// trail) are the same in both, versioned by the same migrations, and written by the same
// statements: parameters are numbered ?1 .. ?N in both dialects (the PostgreSQL connection
// turns them into $1 .. $N), and every value read back is typed (null, integer, real, text).
// A connection is not thread-safe: each store keeps its own behind its own mutex.
#include "devices/record/record_schema.h"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace cutcell {

class RecordError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

using SqlValue = std::variant<std::monostate, std::int64_t, double, std::string>;

// One row of a result; a column read as another type is converted (text parsed in the C
// locale), a null reads as 0 or "".
class SqlRow {
  public:
    explicit SqlRow(std::vector<SqlValue> cells) : cells_(std::move(cells)) {}
    bool isNull(int col) const;
    std::int64_t integer(int col) const;
    double real(int col) const;
    std::string text(int col) const;

  private:
    const SqlValue& at(int col) const;
    std::vector<SqlValue> cells_;
};
using SqlRows = std::vector<SqlRow>;

class RecordDb {
  public:
    virtual ~RecordDb() = default;
    // One statement with parameters ?1 .. ?N; its rows (none for a statement that returns
    // none). Throws RecordError with the database's reason.
    virtual SqlRows query(const std::string& sql, const std::vector<SqlValue>& params = {}) = 0;
    // A write transaction (SQLite: BEGIN IMMEDIATE, so two writers queue at the start).
    virtual void begin() = 0;
    virtual void commit() = 0;
    virtual void rollback() noexcept = 0; // never throws: called while an error unwinds
    virtual int schemaVersion() = 0;
    // "ok" for a sound database, else the checks' findings.
    virtual std::string integrityCheck() = 0;
    // The file, or the server and database as "postgresql://user@host:port/db" (never a
    // password): every message names it.
    virtual const std::string& where() const = 0;
    virtual bool isServer() const = 0;
};

// A rolled-back transaction unless commit() was called.
class RecordTransaction {
  public:
    explicit RecordTransaction(RecordDb& db) : db_(db) { db_.begin(); }
    ~RecordTransaction() {
        if (!done_) db_.rollback();
    }
    RecordTransaction(const RecordTransaction&) = delete;
    RecordTransaction& operator=(const RecordTransaction&) = delete;
    void commit() {
        db_.commit();
        done_ = true;
    }

  private:
    RecordDb& db_;
    bool done_ = false;
};

// A PostgreSQL connection string: a URI (postgresql://, postgres://) or key=value pairs
// (host=... dbname=...). Anything else is a SQLite file's path.
bool isPostgresConnection(const std::string& where);
// Opens (creates, migrates) the record; throws RecordError naming where it is.
std::unique_ptr<RecordDb> openRecordDb(const std::string& where);

// $XDG_DATA_HOME/cutcell/production.db, or ~/.local/share/cutcell/production.db.
std::string defaultProductionDbPath();
std::int64_t unixMsNow();

} // namespace cutcell
