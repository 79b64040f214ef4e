#include "devices/record/pg_record_db.h"

#include <libpq-fe.h>

#include <charconv>

namespace cutcell {
namespace {

// PostgreSQL's built-in type OIDs (catalog/pg_type.dat; fixed since the catalog began).
constexpr Oid kBool = 16, kInt8 = 20, kInt2 = 21, kInt4 = 23, kText = 25, kFloat4 = 700,
              kFloat8 = 701, kNumeric = 1700;

// Serialises the migrations of cells that connect at once (any fixed number; "CUTC").
constexpr const char* kMigrationLock = "SELECT pg_advisory_xact_lock(1129665603)";

// libpq's message on one line (it breaks lines and indents its hints with tabs).
std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' '))
        s.pop_back();
    std::string out;
    for (const char c : s)
        if (c == '\n' || c == '\t') {
            if (!out.empty() && out.back() != ' ') out += ' ';
        } else {
            out += c;
        }
    return out;
}

// PostgreSQL's own words for a failed result: the message, and its detail where it has one.
std::string reasonOf(const PGresult* res, pg_conn* conn) {
    const char* primary = res ? PQresultErrorField(res, PG_DIAG_MESSAGE_PRIMARY) : nullptr;
    if (!primary) return trimmed(PQerrorMessage(conn));
    std::string why = primary;
    // A detail that quotes a row ("Failing row contains (...)") could show a password hash.
    if (const char* detail = PQresultErrorField(res, PG_DIAG_MESSAGE_DETAIL);
        detail && std::string(detail).rfind("Failing row", 0) != 0)
        why += std::string(" (") + detail + ")";
    return why;
}

// "?N" becomes "$N" outside quoted text: one statement text serves both dialects.
std::string dollarParameters(const std::string& sql) {
    std::string out;
    out.reserve(sql.size());
    bool quoted = false;
    for (std::size_t i = 0; i < sql.size(); ++i) {
        const char c = sql[i];
        if (c == '\'') quoted = !quoted;
        const bool numbered = i + 1 < sql.size() && sql[i + 1] >= '0' && sql[i + 1] <= '9';
        out += (c == '?' && !quoted && numbered) ? '$' : c;
    }
    return out;
}

struct ResultFree {
    void operator()(PGresult* r) const { PQclear(r); }
};
using Result = std::unique_ptr<PGresult, ResultFree>;

void ignoreNotice(void*, const char*) {} // "already exists, skipping" and the like

std::string newerSchema(int version) {
    return "schema version " + std::to_string(version) +
           " was written by a newer CutCell (this one knows up to " +
           std::to_string(kProductionDbSchema) + ")";
}

} // namespace

std::string describePostgresConnection(const std::string& connection) {
    char* err = nullptr;
    PQconninfoOption* options = PQconninfoParse(connection.c_str(), &err);
    if (!options) {
        // libpq's message may quote the string, password and all: not shown.
        PQfreemem(err);
        return "postgresql:// (a connection string libpq cannot read; check its syntax)";
    }
    std::string user, host, port, db;
    for (PQconninfoOption* o = options; o->keyword; ++o) {
        if (!o->val) continue;
        const std::string key = o->keyword;
        if (key == "user") user = o->val;
        if (key == "host" || (key == "hostaddr" && host.empty())) host = o->val;
        if (key == "port") port = o->val;
        if (key == "dbname") db = o->val;
    }
    PQconninfoFree(options);
    return "postgresql://" + (user.empty() ? "" : user + "@") +
           (host.empty() ? "localhost" : host) + (port.empty() ? "" : ":" + port) + "/" + db;
}

void PgRecordDb::Closer::operator()(pg_conn* c) const {
    PQfinish(c);
}

PgRecordDb::PgRecordDb(const std::string& connection)
    : where_(describePostgresConnection(connection)) {
    if (char* err = nullptr; PQconninfoOption* o = PQconninfoParse(connection.c_str(), &err))
        PQconninfoFree(o);
    else {
        PQfreemem(err);
        throw RecordError("production record " + where_);
    }
    // Defaults first: the string's own settings given later override them. Keep-alives and a
    // TCP user time-out find a dead server in seconds, not minutes (a store's mutex is held
    // meanwhile); the client encoding is a connection setting, so it survives a reconnect.
    const char* keys[] = {"connect_timeout",
                          "application_name",
                          "keepalives_idle",
                          "keepalives_interval",
                          "keepalives_count",
                          "tcp_user_timeout",
                          "dbname",
                          "client_encoding",
                          nullptr};
    const char* values[] = {"5",     "cutcell",          "10",   "5",    "3",
                            "15000", connection.c_str(), "UTF8", nullptr};
    conn_.reset(PQconnectdbParams(keys, values, 1));
    if (!conn_ || PQstatus(conn_.get()) != CONNECTION_OK)
        throw RecordError("production record " + where_ + ": cannot connect (" +
                          (conn_ ? trimmed(PQerrorMessage(conn_.get())) : "out of memory") + ")");
    PQsetNoticeProcessor(conn_.get(), ignoreNotice, nullptr);
    where_ = "postgresql://" + std::string(PQuser(conn_.get())) + "@" + PQhost(conn_.get()) + ":" +
             PQport(conn_.get()) + "/" + PQdb(conn_.get());
    try {
        migrate();
    } catch (const RecordError& e) {
        throw RecordError("production record " + where_ + ": " + e.what());
    }
}

PgRecordDb::~PgRecordDb() = default;

void PgRecordDb::ensureConnected() {
    if (PQstatus(conn_.get()) == CONNECTION_OK) return;
    if (!inTransaction_) PQreset(conn_.get()); // a transaction's work is gone with its session
    if (PQstatus(conn_.get()) != CONNECTION_OK)
        throw RecordError("production record " + where_ + ": connection lost (" +
                          trimmed(PQerrorMessage(conn_.get())) + ")");
}

void PgRecordDb::exec(const std::string& sql) {
    ensureConnected();
    Result res(PQexec(conn_.get(), sql.c_str()));
    if (PQstatus(conn_.get()) == CONNECTION_BAD && !inTransaction_) { // as in query()
        PQreset(conn_.get());
        if (PQstatus(conn_.get()) == CONNECTION_OK) res.reset(PQexec(conn_.get(), sql.c_str()));
    }
    const ExecStatusType s = res ? PQresultStatus(res.get()) : PGRES_FATAL_ERROR;
    if (s != PGRES_COMMAND_OK && s != PGRES_TUPLES_OK)
        throw RecordError(reasonOf(res.get(), conn_.get()));
}

SqlRows PgRecordDb::query(const std::string& sql, const std::vector<SqlValue>& params) {
    ensureConnected();
    std::vector<std::string> text(params.size());
    std::vector<const char*> values(params.size(), nullptr);
    std::vector<Oid> types(params.size(), 0);
    for (std::size_t i = 0; i < params.size(); ++i) {
        const SqlValue& v = params[i];
        if (const auto* x = std::get_if<std::int64_t>(&v)) {
            text[i] = std::to_string(*x);
            types[i] = kInt8;
        } else if (const auto* d = std::get_if<double>(&v)) {
            char buf[32];
            text[i].assign(buf, std::to_chars(buf, buf + sizeof buf, *d).ptr);
            types[i] = kFloat8;
        } else if (const auto* s = std::get_if<std::string>(&v)) {
            text[i] = *s;
            types[i] = kText;
        } else {
            continue; // NULL, of a type the statement decides
        }
        values[i] = text[i].c_str();
    }
    const std::string statement = dollarParameters(sql);
    const auto run = [&] {
        return Result(PQexecParams(conn_.get(), statement.c_str(), static_cast<int>(params.size()),
                                   types.data(), values.data(), nullptr, nullptr, 0));
    };
    Result res = run();
    // A session the server dropped (a restart, a network cut) fails the statement that meets
    // it before the server runs it: outside a transaction it is sent once more on a new one.
    if (PQstatus(conn_.get()) == CONNECTION_BAD && !inTransaction_) {
        PQreset(conn_.get());
        if (PQstatus(conn_.get()) == CONNECTION_OK) res = run();
    }
    const ExecStatusType s = res ? PQresultStatus(res.get()) : PGRES_FATAL_ERROR;
    if (s != PGRES_COMMAND_OK && s != PGRES_TUPLES_OK)
        throw RecordError("production record: " + reasonOf(res.get(), conn_.get()));
    SqlRows rows;
    const int nRows = PQntuples(res.get()), nCols = PQnfields(res.get());
    rows.reserve(static_cast<std::size_t>(nRows));
    for (int r = 0; r < nRows; ++r) {
        std::vector<SqlValue> cells;
        cells.reserve(static_cast<std::size_t>(nCols));
        for (int c = 0; c < nCols; ++c) {
            if (PQgetisnull(res.get(), r, c)) {
                cells.emplace_back(std::monostate{});
                continue;
            }
            const char* p = PQgetvalue(res.get(), r, c);
            const char* end = p + PQgetlength(res.get(), r, c);
            switch (PQftype(res.get(), c)) {
            case kInt2:
            case kInt4:
            case kInt8: {
                std::int64_t v = 0;
                std::from_chars(p, end, v);
                cells.emplace_back(v);
                break;
            }
            case kFloat4:
            case kFloat8:
            case kNumeric: {
                double v = 0;
                std::from_chars(p, end, v);
                cells.emplace_back(v);
                break;
            }
            case kBool:
                cells.emplace_back(std::int64_t{*p == 't' ? 1 : 0});
                break;
            default:
                cells.emplace_back(std::string(p, end));
            }
        }
        rows.emplace_back(std::move(cells));
    }
    return rows;
}

void PgRecordDb::begin() {
    exec("BEGIN");
    inTransaction_ = true;
}

void PgRecordDb::commit() {
    ensureConnected();
    const Result res(PQexec(conn_.get(), "COMMIT"));
    inTransaction_ = false;
    const ExecStatusType s = res ? PQresultStatus(res.get()) : PGRES_FATAL_ERROR;
    if (s != PGRES_COMMAND_OK) throw RecordError(reasonOf(res.get(), conn_.get()));
    // COMMIT of a transaction that failed earlier answers ROLLBACK without an error.
    if (std::string(PQcmdStatus(res.get())) == "ROLLBACK")
        throw RecordError("the transaction was rolled back by the server");
}

void PgRecordDb::rollback() noexcept {
    if (!inTransaction_) return;
    inTransaction_ = false;
    if (PQstatus(conn_.get()) == CONNECTION_OK) PQclear(PQexec(conn_.get(), "ROLLBACK"));
}

int PgRecordDb::schemaVersion() {
    const SqlRows exists = query("SELECT to_regclass('cutcell_schema') IS NOT NULL");
    if (exists.empty() || exists[0].integer(0) == 0) return 0;
    const SqlRows v = query("SELECT version FROM cutcell_schema");
    return v.empty() ? 0 : static_cast<int>(v[0].integer(0));
}

void PgRecordDb::migrate() {
    if (const int v = schemaVersion(); v == kProductionDbSchema)
        return; // the common case: no lock, no DDL (a reader need not be allowed to create)
    else if (v > kProductionDbSchema)
        throw RecordError(newerSchema(v));
    RecordTransaction tx(*this);
    exec(kMigrationLock); // another cell may be migrating: wait for it, then look again
    exec("CREATE TABLE IF NOT EXISTS cutcell_schema (version INTEGER NOT NULL)");
    if (query("SELECT version FROM cutcell_schema").empty())
        exec("INSERT INTO cutcell_schema VALUES (0)");
    int version = schemaVersion();
    if (version > kProductionDbSchema) throw RecordError(newerSchema(version));
    for (; version < kProductionDbSchema; ++version)
        exec(migrationSql(version, SqlDialect::Postgres));
    query("UPDATE cutcell_schema SET version = ?1", {std::int64_t{kProductionDbSchema}});
    tx.commit();
}

std::string PgRecordDb::integrityCheck() {
    std::string findings;
    const SqlRows orphans = query("SELECT count(*) FROM alarms a WHERE NOT EXISTS (SELECT 1 FROM "
                                  "runs r WHERE r.id = a.run_id)");
    if (!orphans.empty() && orphans[0].integer(0) > 0)
        findings = std::to_string(orphans[0].integer(0)) + " alarm(s) without their run";
    if (query("SELECT 1 FROM pg_extension WHERE extname = 'amcheck'").empty())
        return findings.empty() ? "ok (indexes not checked: no amcheck extension)" : findings;
    const SqlRows may = query("SELECT has_function_privilege('bt_index_check(regclass, boolean)', "
                              "'execute')");
    if (may.empty() || may[0].integer(0) == 0)
        return findings.empty() ? "ok (indexes not checked: this user may not run amcheck)"
                                : findings;
    try {
        // Each B-tree index of the record's tables, its heap included (every row indexed).
        query("SELECT bt_index_check(c.oid, true) FROM pg_index i"
              " JOIN pg_class c ON c.oid = i.indexrelid JOIN pg_class t ON t.oid = i.indrelid"
              " JOIN pg_am am ON am.oid = c.relam WHERE am.amname = 'btree'"
              " AND t.relname IN ('runs', 'alarms', 'users', 'audit', 'audit_state')"
              " AND pg_table_is_visible(t.oid)");
    } catch (const RecordError& e) {
        findings += (findings.empty() ? "" : "; ") + std::string(e.what());
    }
    return findings.empty() ? "ok" : findings;
}

} // namespace cutcell
