#include "devices/record/record_db.h"

#include "devices/record/pg_record_db.h"
#include "devices/record/sqlite_record_db.h"

#include <libpq-fe.h>

#include <charconv>
#include <chrono>
#include <cstdlib>
#include <filesystem>

namespace cutcell {
namespace {

template <class... F> struct Visit : F... { using F::operator()...; };
template <class... F> Visit(F...) -> Visit<F...>; // clang 14 deduces no aggregate

} // namespace

const SqlValue& SqlRow::at(int col) const {
    if (col < 0 || static_cast<std::size_t>(col) >= cells_.size())
        throw RecordError("production record: column " + std::to_string(col) +
                          " read from a row of " + std::to_string(cells_.size()));
    return cells_[static_cast<std::size_t>(col)];
}

bool SqlRow::isNull(int col) const {
    return std::holds_alternative<std::monostate>(at(col));
}

std::int64_t SqlRow::integer(int col) const {
    return std::visit(Visit{[](std::monostate) -> std::int64_t { return 0; },
                            [](std::int64_t v) { return v; },
                            [](double v) { return static_cast<std::int64_t>(v); },
                            [](const std::string& s) {
                                std::int64_t v = 0;
                                std::from_chars(s.data(), s.data() + s.size(), v);
                                return v;
                            }},
                      at(col));
}

double SqlRow::real(int col) const {
    return std::visit(Visit{[](std::monostate) { return 0.0; },
                            [](std::int64_t v) { return static_cast<double>(v); },
                            [](double v) { return v; },
                            [](const std::string& s) {
                                double v = 0;
                                std::from_chars(s.data(), s.data() + s.size(), v);
                                return v;
                            }},
                      at(col));
}

std::string SqlRow::text(int col) const {
    return std::visit(Visit{[](std::monostate) { return std::string(); },
                            [](std::int64_t v) { return std::to_string(v); },
                            [](double v) {
                                char buf[32];
                                const auto r = std::to_chars(buf, buf + sizeof buf, v);
                                return std::string(buf, r.ptr);
                            },
                            [](const std::string& s) { return s; }},
                      at(col));
}

bool isPostgresConnection(const std::string& where) {
    const size_t start = where.find_first_not_of(" \t");
    if (start == std::string::npos) return false;
    const std::string w = where.substr(start);
    if (w.rfind("postgresql://", 0) == 0 || w.rfind("postgres://", 0) == 0) return true;
    // key=value form: its first word is one of libpq's keywords, followed by '='.
    const size_t eq = w.find('=');
    if (eq == std::string::npos) return false;
    std::string key = w.substr(0, eq);
    while (!key.empty() && (key.back() == ' ' || key.back() == '\t'))
        key.pop_back();
    bool known = false;
    if (PQconninfoOption* options = PQconndefaults()) {
        for (const PQconninfoOption* o = options; o->keyword; ++o)
            known = known || key == o->keyword;
        PQconninfoFree(options);
    }
    return known;
}

std::unique_ptr<RecordDb> openRecordDb(const std::string& where) {
    if (isPostgresConnection(where)) return std::make_unique<PgRecordDb>(where);
    return std::make_unique<SqliteRecordDb>(where);
}

std::string defaultProductionDbPath() {
    namespace fs = std::filesystem;
    const char* xdg = std::getenv("XDG_DATA_HOME");
    fs::path base;
    if (xdg && *xdg)
        base = xdg;
    else if (const char* home = std::getenv("HOME"); home && *home)
        base = fs::path(home) / ".local" / "share";
    else
        base = ".";
    return (base / "cutcell" / "production.db").string();
}

std::int64_t unixMsNow() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}

} // namespace cutcell
