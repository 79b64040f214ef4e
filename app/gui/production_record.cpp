#include "production_record.h"

#include "devices/record/run_record_store.h"

namespace cutcell::app {
namespace {

std::shared_ptr<RunRecordStore>& theRecord() {
    static std::shared_ptr<RunRecordStore> record;
    return record;
}

} // namespace

std::string openProductionRecord(const std::string& where) {
    theRecord().reset();
    if (where == "off") return "production record: off (--record off)";
    const std::string path = where.empty() ? RunRecordStore::defaultPath() : where;
    try {
        theRecord() = std::make_shared<RunRecordStore>(path, RunRecordStore::desktopUser());
    } catch (const RecordError& e) {
        return std::string("production record not kept: ") + e.what();
    }
    const int interrupted = theRecord()->interruptedAtOpen();
    std::string line = "production record: " + theRecord()->where();
    if (interrupted > 0)
        line += " (" + std::to_string(interrupted) +
                " run(s) of a station that was killed closed as interrupted)";
    return line;
}

std::shared_ptr<RunRecordSink> productionRecord() {
    return theRecord();
}

RunRecordStore* productionRecordFile() {
    return theRecord().get();
}

} // namespace cutcell::app
