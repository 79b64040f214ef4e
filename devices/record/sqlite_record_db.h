#pragma once
// The production record in one SQLite file (Debian libsqlite3): created with its folder, WAL
// journal, a busy timeout (the GUI and a CLI share the file), foreign keys on, the schema
// versioned by PRAGMA user_version and migrated from any earlier version.
#include "devices/record/record_db.h"

#include <memory>
#include <string>

struct sqlite3;

namespace cutcell {

class SqliteRecordDb final : public RecordDb {
  public:
    // Throws RecordError naming the file and SQLite's reason (a newer schema is refused).
    explicit SqliteRecordDb(const std::string& path);
    ~SqliteRecordDb() override;

    SqlRows query(const std::string& sql, const std::vector<SqlValue>& params = {}) override;
    void begin() override;
    void commit() override;
    void rollback() noexcept override;
    int schemaVersion() override;
    std::string integrityCheck() override; // PRAGMA integrity_check
    const std::string& where() const override { return path_; }
    bool isServer() const override { return false; }

  private:
    struct Closer {
        void operator()(sqlite3* db) const;
    };
    void exec(const char* sql);
    void migrate();
    std::string path_;
    std::unique_ptr<sqlite3, Closer> db_;
};

} // namespace cutcell
