#include "production_record.h"

#include "devices/record/consumable_run_sink.h"
#include "devices/record/run_record_store.h"

#include "core/json/json.h"
#include "core/shopfloor/telemetry_snapshot.h"

#include <mutex>

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

// Every engine's sink: hands each call on to the record (when one is kept) and keeps the figures
// of the last closed run for the shop floor (also without a record). Called on the engines'
// logger threads; read on the GUI thread.
class LastRunTap final : public RunRecordSink {
  public:
    void opened(const RunOpening& run) override {
        if (auto s = inner()) s->opened(run);
    }
    void alarm(const RunAlarmNote& alarm) override {
        if (auto s = inner()) s->alarm(alarm);
    }
    void cutEnded(const RunCutNote& cut) override {
        if (auto s = inner()) s->cutEnded(cut);
    }
    void closed(const RunClosing& run) override {
        keepFigures(run);
        if (auto s = inner()) s->closed(run); // may throw: the run log reports it
    }
    void keepFigures(const RunClosing& run) {
        try {
            const json::Value summary = json::parse(run.summary_json);
            const json::Value* tracking = summary.find("tracking");
            const json::Value* elapsed = summary.find("elapsed_s");
            const json::Value* simulated = tracking ? tracking->find("simulated_s") : nullptr;
            const double cycle = elapsed && elapsed->isNumber()       ? elapsed->asNumber()
                                 : simulated && simulated->isNumber() ? simulated->asNumber()
                                                                      : 0.0;
            auto figures = shopfloor::lastRunFiguresOf(tracking ? *tracking : json::Value(), cycle,
                                                       run.outcome);
            std::lock_guard lock(mutex_);
            last_ = std::move(figures);
        } catch (const std::exception&) {
            // A summary that does not parse: the last figures stay as they were.
        }
    }
    void setInner(std::shared_ptr<RunRecordSink> sink) {
        std::lock_guard lock(mutex_);
        inner_ = std::move(sink);
    }
    std::optional<shopfloor::LastRunFigures> last() const {
        std::lock_guard lock(mutex_);
        return last_;
    }

  private:
    std::shared_ptr<RunRecordSink> inner() const {
        std::lock_guard lock(mutex_);
        return inner_;
    }
    mutable std::mutex mutex_;
    std::shared_ptr<RunRecordSink> inner_;
    std::optional<shopfloor::LastRunFigures> last_;
};

std::shared_ptr<LastRunTap>& theTap() {
    static auto tap = std::make_shared<LastRunTap>();
    return tap;
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
    theTap()->setInner(theSink());
    return theTap();
}

std::optional<shopfloor::LastRunFigures> lastRunFigures() {
    return theTap()->last();
}

RunRecordStore* productionRecordFile() {
    return theRecord().get();
}

ConsumableLedger* consumableLedger() {
    return theLedger();
}

} // namespace cutcell::app
