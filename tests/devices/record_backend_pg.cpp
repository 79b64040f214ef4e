// The record tests against a PostgreSQL server of the test's own (tests/support/
// pg_test_server.h): one cluster for the whole executable, a fresh database per test. Where
// no server can start the executable exits 77, which ctest reports as skipped.
#include "tests/devices/record_backend.h"

#include "devices/record/pg_record_db.h"
#include "devices/record/run_record_store.h"
#include "tests/support/pg_test_server.h"

#include <gtest/gtest.h>
#include <libpq-fe.h>
#include <sqlite3.h>

#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace cutcell::test {
namespace {

PgTestServer& server() {
    static PgTestServer s;
    return s;
}

// Database names: letters, digits and '_' only.
std::string databaseName(const std::string& name) {
    std::string db = "cutcell_" + name;
    for (char& c : db)
        c = std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : '_';
    return db;
}

void execOrThrow(const std::string& where, const std::string& sql) {
    std::string why;
    if (!execOnRecord(where, sql, &why)) throw std::runtime_error(why + " in: " + sql);
}

// The rows of one table of the shipped SQLite file, as INSERTs of literal values.
std::string copyTable(sqlite3* from, PGconn* to, const char* table) {
    std::string sql;
    sqlite3_stmt* st = nullptr;
    sqlite3_prepare_v2(from, (std::string("SELECT * FROM ") + table).c_str(), -1, &st, nullptr);
    while (sqlite3_step(st) == SQLITE_ROW) {
        std::string cols, values;
        for (int c = 0; c < sqlite3_column_count(st); ++c) {
            cols += (c ? ", " : "") + std::string(sqlite3_column_name(st, c));
            std::string v = "NULL";
            if (sqlite3_column_type(st, c) != SQLITE_NULL) {
                const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(st, c));
                char* lit = PQescapeLiteral(to, text, std::strlen(text));
                v = lit;
                PQfreemem(lit);
            }
            values += (c ? ", " : "") + v;
        }
        sql += std::string("INSERT INTO ") + table + " (" + cols + ") VALUES (" + values + ");";
    }
    sqlite3_finalize(st);
    // Rows copied with their ids: the identity goes on after the highest.
    sql += std::string("SELECT setval(pg_get_serial_sequence('") + table + "', 'id'), " +
           "coalesce((SELECT max(id) FROM " + table + "), 1));";
    return sql;
}

} // namespace

const char* recordBackendName() {
    return "postgresql";
}

std::string freshRecord(const std::string& name) {
    const std::string db = databaseName(name);
    std::string why;
    if (!server().createDatabase(db, &why))
        throw std::runtime_error("cannot create database " + db + ": " + why);
    return server().uri(db);
}

bool execOnRecord(const std::string& where, const std::string& sql, std::string* why) {
    return PgTestServer::exec(where, sql, why);
}

void markSchemaVersion(const std::string& where, int version) {
    execOrThrow(where, "CREATE TABLE cutcell_schema (version INTEGER NOT NULL);"
                       "INSERT INTO cutcell_schema VALUES (" +
                           std::to_string(version) + ")");
}

int schemaVersionOf(const std::string& where) {
    PGconn* conn = PQconnectdb(where.c_str());
    PGresult* r = PQexec(conn, "SELECT version FROM cutcell_schema");
    const int version = PQresultStatus(r) == PGRES_TUPLES_OK && PQntuples(r) == 1
                            ? std::atoi(PQgetvalue(r, 0, 0))
                            : -1;
    PQclear(r);
    PQfinish(conn);
    return version;
}

std::string notARecord(const std::string& name) {
    return server().uri(databaseName(name) + "_missing"); // never created
}

std::string schema1Record(const std::string& name) {
    const std::string where = freshRecord(name);
    execOrThrow(where, migrationSql(0, SqlDialect::Postgres));
    markSchemaVersion(where, 1);
    sqlite3* file = nullptr;
    const std::string path =
        std::string(CUTCELL_SOURCE_DIR) + "/tests/data/record/production_schema1.db";
    if (sqlite3_open_v2(path.c_str(), &file, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK)
        throw std::runtime_error("cannot read " + path);
    PGconn* conn = PQconnectdb(where.c_str());
    const std::string sql = copyTable(file, conn, "runs") + copyTable(file, conn, "alarms");
    PQfinish(conn);
    sqlite3_close(file);
    execOrThrow(where, sql);
    return where;
}

std::string recordBytes(const std::string& where) {
    PGconn* conn = PQconnectdb(where.c_str());
    std::string bytes;
    for (const char* table : {"runs", "alarms", "users", "audit"}) {
        PGresult* r = PQexec(conn, (std::string("SELECT t::text FROM ") + table + " t").c_str());
        for (int i = 0; i < PQntuples(r); ++i)
            bytes += std::string(PQgetvalue(r, i, 0)) + "\n";
        PQclear(r);
    }
    PQfinish(conn);
    return bytes;
}

// PostgreSQL's own case: the server restarts under a running station (a shop's server is
// maintained while cells run). The statement that meets the dead session is sent again on a
// new one; nothing written before is lost, the next run is recorded.
TEST(PostgresRecord, AServerRestartUnderAnOpenStoreLosesNothing) {
    const std::string db = freshRecord("restart");
    RunRecordStore record(db, "op");
    record.opened({1, "before", "{}", "", 1000});
    record.closed({"completed", 2000, "{}"});
    ASSERT_TRUE(server().restart());
    EXPECT_EQ(record.runs({}).size(), 1u);
    ASSERT_TRUE(server().restart());
    record.opened({2, "after", "{}", "", 3000}); // the first statement after this restart
    record.closed({"completed", 4000, "{}"});
    EXPECT_EQ(record.runs({}).size(), 2u);
    EXPECT_EQ(record.integrityCheck(), "ok");
}

} // namespace cutcell::test

int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv);
    if (GTEST_FLAG_GET(list_tests)) return RUN_ALL_TESTS();
    std::string why;
    if (!cutcell::test::server().start(&why)) {
        std::printf("SKIP: no PostgreSQL server for the record tests: %s\n", why.c_str());
        return 77;
    }
    std::printf("PostgreSQL test server on 127.0.0.1:%d\n", cutcell::test::server().port());
    // A server's audit archives go to the user's data folder: a temporary one here.
    namespace fs = std::filesystem;
    const fs::path data =
        fs::temp_directory_path() / ("cutcell_pg_data_" + std::to_string(getpid()));
    fs::create_directories(data);
    setenv("XDG_DATA_HOME", data.c_str(), 1);
    const int rc = RUN_ALL_TESTS();
    cutcell::test::server().stop();
    fs::remove_all(data);
    return rc;
}
