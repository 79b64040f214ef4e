#pragma once
// The production record's sink with the consumable statistics (issue 24): every run event goes
// on to the record (`next`), and each cut that ends in a run of a job with a process section is
// counted in the ledger for the job's consumable set - one pierce, its arc-on time and length,
// committed before the next event (RunRecordSink::cutEnded: a program killed mid-run loses only
// the cut under way). Runs of jobs without a process section count nothing.
//
// Threading: called on the engine's logger thread (core/engine/run_log.h), as the record is.
#include "core/process/consumable_counters.h"
#include "core/record/run_record.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace cutcell {

class ConsumableRunSink final : public RunRecordSink {
  public:
    // `problem` hears a ledger that could not be written (the run goes on; the record keeps it).
    ConsumableRunSink(std::shared_ptr<RunRecordSink> next, std::shared_ptr<ConsumableLedger> ledger,
                      std::function<void(const std::string&)> problem = {});

    void opened(const RunOpening& run) override;
    void alarm(const RunAlarmNote& alarm) override;
    void cutEnded(const RunCutNote& cut) override;
    void closed(const RunClosing& run) override;

    // The set the open run's job cuts with (none: no process section, or no run).
    const std::optional<ConsumableSetId>& currentSet() const { return set_; }
    ConsumableLedger* ledger() const { return ledger_.get(); }

  private:
    std::shared_ptr<RunRecordSink> next_;
    std::shared_ptr<ConsumableLedger> ledger_;
    std::function<void(const std::string&)> problem_;
    std::optional<ConsumableSetId> set_;
};

// The ledger on the production record at `where` (its own connection and audit trail, both
// kept alive by the result), wrapped around `record`. Throws RecordError naming `where`.
std::shared_ptr<ConsumableRunSink>
openConsumableRunSink(std::shared_ptr<RunRecordSink> record, const std::string& where,
                      std::function<void(const std::string&)> problem = {});

} // namespace cutcell
