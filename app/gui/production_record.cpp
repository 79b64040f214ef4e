#include "production_record.h"

#include "devices/record/sqlite_run_record.h"

namespace cutcell::app {
namespace {

std::shared_ptr<SqliteRunRecord>& theRecord() {
    static std::shared_ptr<SqliteRunRecord> record;
    return record;
}

} // namespace

std::string openProductionRecord(const std::string& where) {
    theRecord().reset();
    if (where == "off") return "production record: off (--record off)";
    const std::string path = where.empty() ? SqliteRunRecord::defaultPath() : where;
    try {
        theRecord() = std::make_shared<SqliteRunRecord>(path, SqliteRunRecord::desktopUser());
    } catch (const RecordError& e) {
        return std::string("production record not kept: ") + e.what();
    }
    const int interrupted = theRecord()->interruptedAtOpen();
    std::string line = "production record: " + path;
    if (interrupted > 0)
        line += " (" + std::to_string(interrupted) +
                " run(s) of a station that was killed closed as interrupted)";
    return line;
}

std::shared_ptr<RunRecordSink> productionRecord() {
    return theRecord();
}

SqliteRunRecord* productionRecordFile() {
    return theRecord().get();
}

} // namespace cutcell::app
