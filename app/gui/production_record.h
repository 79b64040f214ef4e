#pragma once
// The operator station's production record (devices/record/): opened once at the start (the
// user's data folder's SQLite file, `--record FILE`, or a shop's PostgreSQL server with
// `--record postgresql://user@host:port/db`; `--record off` for none), closing the runs of a
// killed station as interrupted; every rig's engine is told of it (its run logger writes).
#include "core/record/run_record.h"
#include "core/shopfloor/cell_snapshot.h"

#include <memory>
#include <optional>
#include <string>

namespace cutcell {
class RunRecordStore;
class ConsumableLedger;
} // namespace cutcell

namespace cutcell::app {

// Opens the record at `where` ("" = the data folder's, "off" = none). Returns a line for the
// operator (where it is, how many interrupted runs it closed, or why it is not kept: the
// station runs without it then, it never stops a run).
std::string openProductionRecord(const std::string& where);
// What every engine tells of its runs: the record (when one is kept) and the last run's
// figures for the shop floor (never null).
std::shared_ptr<RunRecordSink> productionRecord();
// The figures of the last run any engine closed (none before the first).
std::optional<shopfloor::LastRunFigures> lastRunFigures();
// The same as the file it is (the operator it names follows the log-in); null when none.
RunRecordStore* productionRecordFile();
// The consumable statistics kept in the record (null when none is kept).
ConsumableLedger* consumableLedger();

} // namespace cutcell::app
