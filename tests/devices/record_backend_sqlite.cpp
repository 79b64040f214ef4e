// The record tests against SQLite files in a fresh folder under the temporary directory.
#include "tests/devices/record_backend.h"

#include "core/job/job_io.h"

#include <sqlite3.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace cutcell::test {
namespace {

namespace fs = std::filesystem;

// The folders made for this process's records, removed when it ends.
struct Folders {
    std::vector<fs::path> made;
    ~Folders() {
        std::error_code ec;
        for (const fs::path& dir : made)
            fs::remove_all(dir, ec);
    }
};

fs::path freshDir(const std::string& name) {
    static Folders folders;
    const fs::path dir =
        fs::temp_directory_path() / ("cutcell_record_" + name + "_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    folders.made.push_back(dir);
    return dir;
}

} // namespace

const char* recordBackendName() {
    return "sqlite";
}

std::string freshRecord(const std::string& name) {
    return (freshDir(name) / "sub" / "p.db").string(); // the folder is made by the record
}

bool execOnRecord(const std::string& where, const std::string& sql, std::string* why) {
    sqlite3* raw = nullptr;
    bool ok = sqlite3_open(where.c_str(), &raw) == SQLITE_OK;
    char* err = nullptr;
    ok = ok && sqlite3_exec(raw, sql.c_str(), nullptr, nullptr, &err) == SQLITE_OK;
    if (!ok && why) *why = err ? err : sqlite3_errmsg(raw);
    sqlite3_free(err);
    sqlite3_close(raw);
    return ok;
}

void markSchemaVersion(const std::string& where, int version) {
    fs::create_directories(fs::path(where).parent_path());
    if (!execOnRecord(where, "PRAGMA user_version = " + std::to_string(version) + ";"))
        throw std::runtime_error("cannot mark " + where);
}

int schemaVersionOf(const std::string& where) {
    sqlite3* raw = nullptr;
    int version = -1;
    if (sqlite3_open_v2(where.c_str(), &raw, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
        sqlite3_stmt* st = nullptr;
        sqlite3_prepare_v2(raw, "PRAGMA user_version", -1, &st, nullptr);
        if (sqlite3_step(st) == SQLITE_ROW) version = sqlite3_column_int(st, 0);
        sqlite3_finalize(st);
    }
    sqlite3_close(raw);
    return version;
}

std::string notARecord(const std::string& name) {
    const std::string text = (freshDir(name) / "notes.txt").string();
    writeFileAtomically(text, "these are not the droids you are looking for\n");
    return text;
}

std::string schema1Record(const std::string& name) {
    const fs::path db = freshDir(name) / "old.db";
    fs::copy_file(fs::path(CUTCELL_SOURCE_DIR) / "tests/data/record/production_schema1.db", db);
    return db.string();
}

std::string recordBytes(const std::string& where) {
    std::string bytes;
    for (const char* suffix : {"", "-wal"}) {
        std::ifstream in(where + suffix, std::ios::binary);
        bytes.append(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    return bytes;
}

} // namespace cutcell::test
