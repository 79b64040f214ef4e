#include "devices/record/audit_trail.h"

#include "core/job/job_io.h"
#include "core/json/json.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

namespace cutcell {
namespace {

namespace fs = std::filesystem;

std::int64_t countRows(RecordDb& db) {
    const SqlRows r = db.query("SELECT count(*) FROM audit");
    return r.empty() ? 0 : r[0].integer(0);
}

void insert(RecordDb& db, const AuditEvent& e) {
    db.query("INSERT INTO audit (time_ms, actor, event, key, old_value, new_value, unit, "
             "detail) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)",
             {e.unix_ms > 0 ? e.unix_ms : unixMsNow(), e.actor, e.event, e.key, e.old_value,
              e.new_value, e.unit, e.detail});
}

// "<file>.audit" beside a file; a server's archive goes to this station's data folder, named
// after the server and database ("postgresql://u@h:5432/db" -> "h_5432_db.audit").
std::string archiveDirOf(const RecordDb& db) {
    if (!db.isServer()) return db.where() + ".audit";
    std::string name = db.where().substr(db.where().find('@') + 1);
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
    return (fs::path(defaultProductionDbPath()).parent_path() / (name + ".audit")).string();
}

} // namespace

AuditTrail::AuditTrail(const std::string& where, std::int64_t maxRecords)
    : maxRecords_(std::max<std::int64_t>(10, maxRecords)), db_(openRecordDb(where)),
      archiveDir_(archiveDirOf(*db_)) {}

AuditTrail::~AuditTrail() = default;

void AuditTrail::append(const AuditEvent& event) {
    std::lock_guard<std::mutex> lock(mutex_);
    insert(*db_, event);
    // Counted once, then kept (other writers' rows are found at the next roll's count): a
    // full count per event would scan the table each time.
    rows_ = rows_ < 0 ? countRows(*db_) : rows_ + 1;
    if (rows_ > maxRecords_ && rows_ >= rollRetryAt_) rollIfFull();
}

// Past the bound the oldest tenth goes to an archive file first (outside any transaction: a
// slow disk holds no lock), then leaves the table in one write transaction that marks
// audit_state.archiving (the delete trigger lets rows out only while it is set; the mark also
// makes two rolling stations wait for each other). The delete goes ahead only if the table
// still holds exactly the archived rows up to the last one: a row another station committed
// meanwhile below that id (ids are handed out before commit), or a roll of another station,
// makes this one give up and try again later. A crash between the file and the commit leaves
// the records in both places, never in neither.
void AuditTrail::rollIfFull() {
    RecordDb& db = *db_;
    const std::int64_t rows = rows_ = countRows(db);
    if (rows <= maxRecords_) return;
    const std::int64_t roll = rows - (maxRecords_ - maxRecords_ / 10);
    std::string lines;
    std::int64_t first = 0, last = 0, archived = 0;
    for (const SqlRow& r : db.query("SELECT id, time_ms, actor, event, key, old_value, "
                                    "new_value, unit, detail FROM audit ORDER BY id LIMIT ?1",
                                    {roll})) {
        const AuditEvent e{r.integer(1), r.text(2), r.text(3), r.text(4),
                           r.text(5),    r.text(6), r.text(7), r.text(8)};
        last = r.integer(0);
        if (first == 0) first = last;
        lines += json::write(toJson({last, e}), -1); // one line, ending in a line break
        ++archived;
    }
    const fs::path file = fs::path(archiveDir_) / ("audit-" + std::to_string(first) + "-" +
                                                   std::to_string(last) + ".jsonl");
    const auto retryLater = [&] {
        rollRetryAt_ = rows + std::max<std::int64_t>(1, maxRecords_ / 10);
    };
    try {
        fs::create_directories(archiveDir_);
        // The archive is a new plain file: a link or a pipe planted under its name is refused.
        if (std::error_code ec; fs::exists(fs::symlink_status(file, ec)) &&
                                !fs::is_regular_file(fs::symlink_status(file, ec)))
            throw std::runtime_error("it exists and is not a plain file");
        writeFileAtomically(file.string(), lines);
    } catch (const std::exception& e) {
        retryLater(); // after another tenth of the bound, not at every event
        throw RecordError("audit trail " + db.where() + ": " + std::to_string(rows) +
                          " records exceed the bound of " + std::to_string(maxRecords_) +
                          " and the archive " + file.string() +
                          " cannot be written (every record is kept): " + e.what());
    }
    RecordTransaction tx(db);
    db.query("UPDATE audit_state SET archiving = 1");
    const SqlRows held =
        db.query("SELECT count(*), coalesce(min(id), 0) FROM audit WHERE id <= ?1", {last});
    if (held.empty() || held[0].integer(0) != archived || held[0].integer(1) != first) {
        retryLater(); // the transaction rolls back; the file holds copies only
        std::error_code ec;
        fs::remove(file, ec);
        return;
    }
    db.query("DELETE FROM audit WHERE id <= ?1", {last});
    db.query("UPDATE audit_state SET archiving = 0");
    insert(db, {0, "cutcell", audit_event::kArchived, "", "", "", "",
                std::to_string(roll) + " records (" + std::to_string(first) + " to " +
                    std::to_string(last) + ") moved to " + file.string()});
    tx.commit();
    rows_ = countRows(db);
}

std::vector<RecordedAuditEvent> AuditTrail::events(std::int64_t sinceMs) const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<RecordedAuditEvent> out;
    for (const SqlRow& r : db_->query("SELECT id, time_ms, actor, event, key, old_value, "
                                      "new_value, unit, detail FROM audit WHERE time_ms >= ?1 "
                                      "ORDER BY id",
                                      {sinceMs}))
        out.push_back({r.integer(0),
                       {r.integer(1), r.text(2), r.text(3), r.text(4), r.text(5), r.text(6),
                        r.text(7), r.text(8)}});
    return out;
}

json::Value AuditTrail::toJson(const RecordedAuditEvent& r) {
    const AuditEvent& e = r.event;
    return json::Object{{"id", static_cast<double>(r.id)},
                        {"time_ms", static_cast<double>(e.unix_ms)},
                        {"actor", e.actor},
                        {"event", e.event},
                        {"key", e.key},
                        {"old", e.old_value},
                        {"new", e.new_value},
                        {"unit", e.unit},
                        {"detail", e.detail}};
}

std::int64_t AuditTrail::count() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return countRows(*db_);
}

} // namespace cutcell
