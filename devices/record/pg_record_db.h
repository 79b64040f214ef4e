#pragma once
// The production record on a PostgreSQL server (Debian libpq), for a shop whose cells share one
// record: the same tables as the SQLite file (runs, alarms, users, the append-only audit
// trail), the same schema versions and migrations in PostgreSQL's words, the version in a
// table (cutcell_schema) and migrations serialised between cells by an advisory lock. Selected
// by a connection string (postgresql://user@host:port/db or host=... dbname=...); a password
// in it is never printed. A connection lost between statements is re-established once.
#include "devices/record/record_db.h"

#include <memory>
#include <string>

struct pg_conn;

namespace cutcell {

class PgRecordDb final : public RecordDb {
  public:
    // Connects (5 s timeout unless the string sets connect_timeout) and migrates; throws
    // RecordError naming the server and database and PostgreSQL's reason.
    explicit PgRecordDb(const std::string& connection);
    ~PgRecordDb() override;

    SqlRows query(const std::string& sql, const std::vector<SqlValue>& params = {}) override;
    void begin() override;
    void commit() override;
    void rollback() noexcept override;
    int schemaVersion() override;
    // Alarms without their run, and, where the database has the amcheck extension, every
    // B-tree index of the record's tables checked; "ok" when all passed. Without amcheck:
    // "ok (indexes not checked: no amcheck extension)".
    std::string integrityCheck() override;
    const std::string& where() const override { return where_; }
    bool isServer() const override { return true; }

  private:
    struct Closer {
        void operator()(pg_conn* c) const;
    };
    void exec(const std::string& sql); // one or more statements without parameters
    void ensureConnected();
    void migrate();
    std::string where_;
    std::unique_ptr<pg_conn, Closer> conn_;
    bool inTransaction_ = false;
};

// The connection string as messages may show it: postgresql://user@host:port/db, without any
// password.
std::string describePostgresConnection(const std::string& connection);

} // namespace cutcell
