#include "devices/record/consumable_ledger_store.h"
#include "devices/record/run_record_store.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <stdexcept>

namespace cutcell {
namespace {

// The columns every query reads, in ConsumableCounters' order (readRow()).
constexpr const char* kColumns = "id, process, consumable, installed_ms, coalesce(removed_ms, 0), "
                                 "removed_by, removal_reason, cuts, pierces, arc_on_ms, "
                                 "cut_length_mm";
// The set's row now in the torch (?1 station, ?2 process, ?3 consumable).
constexpr const char* kCurrent =
    " WHERE station = ?1 AND process = ?2 AND consumable = ?3 AND removed_ms IS NULL";

ConsumableCounters readRow(const SqlRow& r) {
    ConsumableCounters c;
    c.id = r.integer(0);
    c.set.process = cutProcessFromString(r.text(1)).value_or(CutProcess::Plasma);
    c.set.consumable = r.text(2);
    c.installed_ms = r.integer(3);
    c.removed_ms = r.integer(4);
    c.removed_by = r.text(5);
    c.removal_reason = r.text(6);
    c.cuts = r.integer(7);
    c.pierces = r.integer(8);
    c.arc_on_ms = r.integer(9);
    c.cut_length_mm = r.real(10);
    return c;
}

ConsumableCounters firstOr(const SqlRows& rows, const ConsumableSetId& set) {
    if (!rows.empty()) return readRow(rows[0]);
    ConsumableCounters none;
    none.set = set;
    return none;
}

void checkSet(const ConsumableSetId& set) {
    if (set.consumable.empty())
        throw std::invalid_argument("consumables: a set without a name (the cut chart's "
                                    "consumable) cannot be counted");
}

// A figure of a cut: finite, >= 0 and below a bound no single cut reaches.
void checkFigure(const char* what, double v, const char* unit, double below) {
    if (std::isfinite(v) && v >= 0 && v < below) return;
    char buf[160];
    std::snprintf(buf, sizeof buf, "consumables: a cut's %s of %g %s is not counted (0 .. %g %s)",
                  what, v, unit, below, unit);
    throw std::invalid_argument(buf);
}

std::string counts(const ConsumableCounters& c) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%lld pierces, %.3f s arc-on, %.1f mm cut, %lld cuts",
                  static_cast<long long>(c.pierces), c.arcOnS(), c.cut_length_mm,
                  static_cast<long long>(c.cuts));
    return buf;
}

std::string utcTime(std::int64_t ms) {
    const std::time_t t = static_cast<std::time_t>(ms / 1000);
    std::tm tm{};
    char buf[32] = "?";
    if (gmtime_r(&t, &tm)) std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
    return buf;
}

} // namespace

ConsumableLedgerStore::ConsumableLedgerStore(const std::string& where, AuditSink& audit,
                                             std::string station, Clock clock)
    : audit_(audit), station_(station.empty() ? thisStation() : std::move(station)),
      clock_(std::move(clock)), db_(openRecordDb(where)) {
    // A count must survive a power cut, not only a kill: the WAL synced at every commit,
    // whatever the SQLite build's default (Debian's is FULL too; NORMAL would sync only at
    // checkpoints and could lose the last cuts).
    if (!db_->isServer()) db_->query("PRAGMA synchronous=FULL");
}

ConsumableLedgerStore::~ConsumableLedgerStore() = default;

ConsumableCounters ConsumableLedgerStore::current(const ConsumableSetId& set) const {
    std::lock_guard<std::mutex> lock(mutex_);
    return firstOr(
        db_->query(std::string("SELECT ") + kColumns + " FROM consumable_sets" + kCurrent,
                   {station_, std::string(toString(set.process)), set.consumable}),
        set);
}

// One transaction: the cut is in the counters after the commit, or not at all (a kill before
// it rolls the write back at the next open). The first cut of a set installs it.
ConsumableCounters ConsumableLedgerStore::recordCut(const ConsumableSetId& set,
                                                    std::int64_t pierces, double arc_s,
                                                    double length_mm) {
    checkSet(set);
    checkFigure("pierce count", static_cast<double>(pierces), "pierces", 1e6);
    checkFigure("arc-on time", arc_s, "s", 1e7);
    checkFigure("cut length", length_mm, "mm", 1e9);
    const std::int64_t arcMs = std::llround(arc_s * 1000.0);
    const std::string process = toString(set.process);
    std::lock_guard<std::mutex> lock(mutex_);
    RecordTransaction tx(*db_);
    SqlRows rows = db_->query(
        std::string("UPDATE consumable_sets SET cuts = cuts + 1, pierces = pierces + ?4, "
                    "arc_on_ms = arc_on_ms + ?5, cut_length_mm = cut_length_mm + ?6") +
            kCurrent + " RETURNING " + kColumns,
        {station_, process, set.consumable, pierces, arcMs, length_mm});
    if (rows.empty())
        rows = db_->query(std::string("INSERT INTO consumable_sets (station, process, consumable, "
                                      "installed_ms, cuts, pierces, arc_on_ms, cut_length_mm) "
                                      "VALUES (?1, ?2, ?3, ?7, 1, ?4, ?5, ?6) RETURNING ") +
                              kColumns,
                          {station_, process, set.consumable, pierces, arcMs, length_mm, clock_()});
    tx.commit();
    return firstOr(rows, set);
}

// The old row is closed and the new one opened in one transaction (never two sets in the torch,
// never none); the audit trail, a connection of its own, gets the event after the commit, as
// UserDirectory does: the row itself keeps who and why should the event be lost to a crash
// between the two.
ConsumableCounters ConsumableLedgerStore::replace(const ConsumableSetId& set,
                                                  const std::string& user,
                                                  const std::string& reason) {
    checkSet(set);
    if (user.empty())
        throw std::invalid_argument("consumables: a replacement must name who made it");
    const std::string process = toString(set.process);
    std::lock_guard<std::mutex> lock(mutex_);
    const std::int64_t now = clock_();
    RecordTransaction tx(*db_);
    const SqlRows old =
        db_->query(std::string("UPDATE consumable_sets SET removed_ms = ?4, removed_by = ?5, "
                               "removal_reason = ?6") +
                       kCurrent + " RETURNING " + kColumns,
                   {station_, process, set.consumable, now, user, reason});
    const SqlRows fresh =
        db_->query(std::string("INSERT INTO consumable_sets (station, process, consumable, "
                               "installed_ms) VALUES (?1, ?2, ?3, ?4) RETURNING ") +
                       kColumns,
                   {station_, process, set.consumable, now});
    tx.commit();
    const ConsumableCounters was = firstOr(old, set), fitted = firstOr(fresh, set);
    audit_.append({now, user, kConsumablesReplacedEvent, set.name(),
                   old.empty() ? "none recorded" : counts(was), counts(fitted), "",
                   "reason: " + (reason.empty() ? std::string("(none given)") : reason) +
                       "; station " + station_ +
                       (old.empty() ? "" : "; installed " + utcTime(was.installed_ms))});
    return fitted;
}

std::vector<ConsumableCounters> ConsumableLedgerStore::history(const ConsumableSetId& set) const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<ConsumableCounters> out;
    // The current row (removed_ms NULL) sorts last: ids grow, and it is the newest.
    for (const SqlRow& r :
         db_->query(std::string("SELECT ") + kColumns +
                        " FROM consumable_sets WHERE station = ?1 AND "
                        "process = ?2 AND consumable = ?3 ORDER BY id",
                    {station_, std::string(toString(set.process)), set.consumable}))
        out.push_back(readRow(r));
    return out;
}

ConsumableTotals ConsumableLedgerStore::totals() const {
    std::lock_guard<std::mutex> lock(mutex_);
    const SqlRows r = db_->query("SELECT count(*), coalesce(sum(cuts), 0), coalesce(sum(pierces), "
                                 "0), coalesce(sum(arc_on_ms), 0), coalesce(sum(cut_length_mm), 0)"
                                 " FROM consumable_sets WHERE station = ?1",
                                 {station_});
    if (r.empty()) return {};
    return {r[0].integer(0), r[0].integer(1), r[0].integer(2), r[0].integer(3), r[0].real(4)};
}

std::string ConsumableLedgerStore::thisStation() {
    return recordHostName();
}

} // namespace cutcell
