#pragma once
// The audit trail in the production record, a SQLite file or a PostgreSQL database (IEC 62443-4-2
// CR 2.8 auditable events, CR 2.9 audit storage capacity): one row per event - who, when, what, the
// key, old and new value with the unit. Append-only: the program has no call that edits or deletes
// an event, and the database's triggers refuse an UPDATE and any DELETE outside an archiving roll.
// Bounded: past `maxRecords` the oldest tenth is first written to an archive file (JSON Lines,
// atomically, in archiveDir()), then removed from the table in one transaction, and the
// roll itself is an event naming the file: nothing is dropped silently.
#include "core/json/json.h"
#include "core/record/audit.h"
#include "devices/record/record_db.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace cutcell {

struct RecordedAuditEvent {
    std::int64_t id = 0;
    AuditEvent event;
};

class AuditTrail final : public AuditSink {
  public:
    static constexpr std::int64_t kDefaultMaxRecords = 1'000'000;

    // Opens (creates, migrates) the record `where` (record_db.h); throws RecordError.
    explicit AuditTrail(const std::string& where, std::int64_t maxRecords = kDefaultMaxRecords);
    ~AuditTrail() override;
    AuditTrail(const AuditTrail&) = delete;
    AuditTrail& operator=(const AuditTrail&) = delete;

    // Throws RecordError (the record cannot be written); an archive that cannot be written
    // keeps every record in the table and says so in the error.
    void append(const AuditEvent& event) override;

    std::vector<RecordedAuditEvent> events(std::int64_t sinceMs = 0) const; // oldest first
    std::int64_t count() const;
    // The file, or the server and database (no password).
    const std::string& where() const { return db_->where(); }
    // One event as the archive's JSON Lines and `cutcell-cli audit --json` write it.
    static json::Value toJson(const RecordedAuditEvent& r);
    // The folder the rolled records go to: "<file>.audit" beside a SQLite file; for a server,
    // "<user data>/cutcell/<host>_<port>_<db>.audit" on the station that rolled them.
    const std::string& archiveDir() const { return archiveDir_; }

  private:
    void rollIfFull();
    std::int64_t maxRecords_;
    std::unique_ptr<RecordDb> db_; // [mutex_]
    std::string archiveDir_;
    mutable std::mutex mutex_;
    std::int64_t rows_ = -1;       // [mutex_] this connection's count (-1: not counted yet)
    std::int64_t rollRetryAt_ = 0; // [mutex_] a failed roll is tried again at this count
};

} // namespace cutcell
