#pragma once
// The audit trail in the production record's SQLite file (IEC 62443-4-2 CR 2.8 auditable
// events, CR 2.9 audit storage capacity): one row per event - who, when, what, the key, old
// and new value with the unit. Append-only: the program has no call that edits or deletes an
// event, and the file's triggers refuse an UPDATE and any DELETE outside an archiving roll.
// Bounded: past `maxRecords` the oldest tenth is first written to an archive file (JSON Lines,
// atomically, in `<record>.audit/`), then removed from the table in one transaction, and the
// roll itself is an event naming the file: nothing is dropped silently.
#include "core/json/json.h"
#include "core/record/audit.h"
#include "devices/record/production_db.h"

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace cutcell {

struct RecordedAuditEvent {
    std::int64_t id = 0;
    AuditEvent event;
};

class SqliteAuditTrail final : public AuditSink {
  public:
    static constexpr std::int64_t kDefaultMaxRecords = 1'000'000;

    // Opens (creates, migrates) the record at `path`; throws RecordError.
    explicit SqliteAuditTrail(const std::string& path,
                              std::int64_t maxRecords = kDefaultMaxRecords);
    ~SqliteAuditTrail() override;
    SqliteAuditTrail(const SqliteAuditTrail&) = delete;
    SqliteAuditTrail& operator=(const SqliteAuditTrail&) = delete;

    // Throws RecordError (the file cannot be written); an archive that cannot be written
    // keeps every record in the table and says so in the error.
    void append(const AuditEvent& event) override;

    std::vector<RecordedAuditEvent> events(std::int64_t sinceMs = 0) const; // oldest first
    std::int64_t count() const;
    // One event as the archive's JSON Lines and `cutcell-cli audit --json` write it.
    static json::Value toJson(const RecordedAuditEvent& r);
    // The folder the rolled records go to: "<record>.audit".
    std::string archiveDir() const { return path_ + ".audit"; }

  private:
    void rollIfFull();
    std::string path_;
    std::int64_t maxRecords_;
    SqliteHandle db_;
    mutable std::mutex mutex_;
    std::int64_t rows_ = -1;       // [mutex_] this connection's count (-1: not counted yet)
    std::int64_t rollRetryAt_ = 0; // [mutex_] a failed roll is tried again at this count
};

} // namespace cutcell
