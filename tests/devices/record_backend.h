#pragma once
// Where the production record's tests keep their record: the same tests (run_record_test.cpp,
// users_audit_test.cpp) are built twice, against SQLite files (record_backend_sqlite.cpp) and
// against a PostgreSQL server the test starts itself (record_backend_pg.cpp), so both databases
// pass exactly the same checks.
#include <string>

namespace cutcell::test {

// "sqlite" or "postgresql".
const char* recordBackendName();
// A new, empty record for one test (a file in a fresh folder, or a fresh database); its
// connection string or path.
std::string freshRecord(const std::string& name);
// Runs SQL on the record as another program would, beside CutCell; false with the database's
// reason in *why.
bool execOnRecord(const std::string& where, const std::string& sql, std::string* why = nullptr);
// Marks an empty record as written by a newer CutCell (schema version `version`).
void markSchemaVersion(const std::string& where, int version);
// The schema version the record says it has, read as another program would (0: none).
int schemaVersionOf(const std::string& where);
// Something given as a record that is none (a text file; a database that does not exist).
std::string notARecord(const std::string& name);
// A record of schema 1 holding the two runs of tests/data/record/production_schema1.db (the
// file the code before users wrote; for PostgreSQL, its rows in a schema-1 database).
std::string schema1Record(const std::string& name);
// Everything the record stores, as bytes (the file and its journal; the tables' text).
std::string recordBytes(const std::string& where);

} // namespace cutcell::test
