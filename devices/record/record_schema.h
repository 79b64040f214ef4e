#pragma once
// The production record's schema, written once for both databases: migration k takes a record
// from schema version k to k + 1. The tables and columns are the same text for SQLite and
// PostgreSQL with the types put in per dialect (an id, an integer, a real); only what the SQL
// languages say differently (the audit trail's append-only triggers) is written twice. Never
// edited once shipped: tests/data/record/ keeps a SQLite file of each earlier schema.
#include <string>

namespace cutcell {

inline constexpr int kProductionDbSchema = 3;

enum class SqlDialect { Sqlite, Postgres };

// The SQL (several statements) of migration `from` -> from + 1; "" outside [0, schema).
std::string migrationSql(int from, SqlDialect dialect);

} // namespace cutcell
