#include "production_record.h"

#include "devices/record/consumable_run_sink.h"
#include "devices/record/run_record_store.h"

namespace cutcell::app {
namespace {

std::shared_ptr<RunRecordStore>& theRecord() {
    static std::shared_ptr<RunRecordStore> record;
    return record;
}

// The record with the consumable statistics counted into it (null: no record, or the ledger
// could not be opened - the record is then handed on alone).
std::shared_ptr<RunRecordSink>& theSink() {
    static std::shared_ptr<RunRecordSink> sink;
    return sink;
}

ConsumableLedger*& theLedger() {
    static ConsumableLedger* ledger = nullptr;
    return ledger;
}

} // namespace

std::string openProductionRecord(const std::string& where) {
    theRecord().reset();
    theSink().reset();
    theLedger() = nullptr;
    if (where == "off") return "production record: off (--record off)";
    const std::string path = where.empty() ? RunRecordStore::defaultPath() : where;
    try {
        theRecord() = std::make_shared<RunRecordStore>(path, RunRecordStore::desktopUser());
    } catch (const RecordError& e) {
        return std::string("production record not kept: ") + e.what();
    }
    const int interrupted = theRecord()->interruptedAtOpen();
    std::string line = "production record: " + theRecord()->where();
    try {
        auto sink = openConsumableRunSink(theRecord(), theRecord()->where());
        theLedger() = sink->ledger();
        theSink() = std::move(sink);
    } catch (const RecordError& e) {
        theSink() = theRecord();
        line += std::string(" (consumable statistics not kept: ") + e.what() + ")";
    }
    if (interrupted > 0)
        line += " (" + std::to_string(interrupted) +
                " run(s) of a station that was killed closed as interrupted)";
    return line;
}

std::shared_ptr<RunRecordSink> productionRecord() {
    return theSink();
}

RunRecordStore* productionRecordFile() {
    return theRecord().get();
}

ConsumableLedger* consumableLedger() {
    return theLedger();
}

} // namespace cutcell::app
