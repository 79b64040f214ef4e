#pragma once
// The consumable ledger (core/process/consumable_counters.h) in the production record, a SQLite
// file or a PostgreSQL database (record_db.h; table consumable_sets, schema 3): one row per set
// installed in a station's torch, holding its counters; a replaced set keeps its row as
// history, with who replaced it, when and why, and the replacement is an audit-trail event.
//
// Durability: each recordCut() is one write transaction, committed before it returns. On SQLite
// this connection runs with journal_mode=WAL (sqlite_record_db.cpp) and synchronous=FULL (set
// here: the WAL is synced at every commit, so a commit survives a kill and a power cut); on
// PostgreSQL a commit is what the server's synchronous_commit makes it (on by default).
//
// Stations sharing a server's record each count their own torch: rows are keyed by station (by
// default this host's name and machine id, as the runs' host column has them).
#include "core/process/consumable_counters.h"
#include "core/record/audit.h"
#include "devices/record/record_db.h"

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace cutcell {

class ConsumableLedgerStore final : public ConsumableLedger {
  public:
    using Clock = std::function<std::int64_t()>; // ms since the epoch

    // Opens (creates, migrates) the record `where`; throws RecordError naming it. `audit`
    // outlives this; "" as station is thisStation().
    ConsumableLedgerStore(const std::string& where, AuditSink& audit, std::string station = {},
                          Clock clock = unixMsNow);
    ~ConsumableLedgerStore() override;
    ConsumableLedgerStore(const ConsumableLedgerStore&) = delete;
    ConsumableLedgerStore& operator=(const ConsumableLedgerStore&) = delete;

    ConsumableCounters current(const ConsumableSetId& set) const override;
    ConsumableCounters recordCut(const ConsumableSetId& set, std::int64_t pierces, double arc_s,
                                 double length_mm) override;
    ConsumableCounters replace(const ConsumableSetId& set, const std::string& user,
                               const std::string& reason) override;
    std::vector<ConsumableCounters> history(const ConsumableSetId& set) const override;
    ConsumableTotals totals() const override;

    const std::string& station() const { return station_; }
    const std::string& where() const { return db_->where(); }
    // "host (machine-id's first 12 hex digits)", as RunRecordStore names a run's host.
    static std::string thisStation();

  private:
    AuditSink& audit_;
    std::string station_;
    Clock clock_;
    std::unique_ptr<RecordDb> db_; // [mutex_]
    mutable std::mutex mutex_;
};

} // namespace cutcell
