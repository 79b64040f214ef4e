#include "devices/record/consumable_run_sink.h"

#include "core/job/job_io.h"
#include "devices/record/audit_trail.h"
#include "devices/record/consumable_ledger_store.h"

#include <exception>

namespace cutcell {

ConsumableRunSink::ConsumableRunSink(std::shared_ptr<RunRecordSink> next,
                                     std::shared_ptr<ConsumableLedger> ledger,
                                     std::function<void(const std::string&)> problem)
    : next_(std::move(next)), ledger_(std::move(ledger)), problem_(std::move(problem)) {}

void ConsumableRunSink::opened(const RunOpening& run) {
    set_.reset();
    try {
        // The run's own job file: what it cuts with, whatever the editor shows now.
        const Job job = parseJob(run.job_text);
        if (job.process.used) set_ = ConsumableSetId{job.process.process, job.process.consumable};
    } catch (const std::exception&) {
        // A job the engine runs was validated; a text that does not parse counts nothing.
    }
    if (next_) next_->opened(run);
}

void ConsumableRunSink::alarm(const RunAlarmNote& alarm) {
    if (next_) next_->alarm(alarm);
}

void ConsumableRunSink::cutEnded(const RunCutNote& cut) {
    if (set_ && ledger_) {
        try {
            ledger_->recordCut(*set_, 1, cut.tool_on_s, cut.length_mm);
        } catch (const std::exception& e) {
            if (problem_) problem_(std::string("consumable statistics: ") + e.what());
        }
    }
    if (next_) next_->cutEnded(cut);
}

void ConsumableRunSink::closed(const RunClosing& run) {
    set_.reset();
    if (next_) next_->closed(run);
}

namespace {
// The store refers to its audit trail: both live as long as the ledger handed out.
struct OwnedLedger {
    explicit OwnedLedger(const std::string& where) : trail(where), store(where, trail) {}
    AuditTrail trail;
    ConsumableLedgerStore store;
};
} // namespace

std::shared_ptr<ConsumableRunSink>
openConsumableRunSink(std::shared_ptr<RunRecordSink> record, const std::string& where,
                      std::function<void(const std::string&)> problem) {
    auto owned = std::make_shared<OwnedLedger>(where);
    std::shared_ptr<ConsumableLedger> ledger(owned, &owned->store);
    return std::make_shared<ConsumableRunSink>(std::move(record), std::move(ledger),
                                               std::move(problem));
}

} // namespace cutcell
