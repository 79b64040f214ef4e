#pragma once
// Consumable statistics (issue 24): what the consumable set now in the torch has done - pierces,
// arc-on time, cut length - against the life its cut chart expects, and the ledger that keeps
// them across restarts (devices/record/: ConsumableLedgerStore, in the production record).
//
// A cut counts when it is COMPLETED, from its pierce to its arc off: the ledger gets it once,
// then, as one durable write. A cut stopped early (feed hold, E-STOP) also ends at its arc off
// and should be recorded with what it did (its pierce and arc time wore the set); only the cut
// in progress when the program is killed or the power fails is lost. Arc-on time is kept in whole
// milliseconds: integer sums stay exact over a set's life (a real sum drifts by its rounding at
// every cut), and the levels below compare integers, so 90 % is 90 % and not 89.99999 %.
#include "core/process/cut_chart.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cutcell {

// Which set: the process and the cut chart's consumable name ("Powermax65/85 45A shielded").
struct ConsumableSetId {
    CutProcess process = CutProcess::Plasma;
    std::string consumable;
    // "plasma / Powermax65/85 45A shielded": the audit trail's key.
    std::string name() const;
    bool operator==(const ConsumableSetId&) const = default;
};

// One set from its installation on (a set replaced keeps its row, as history).
struct ConsumableCounters {
    std::int64_t id = 0; // the ledger's number of this installation; 0: not in the ledger yet
    ConsumableSetId set;
    std::int64_t installed_ms = 0; // since the epoch (its first cut, or its replace()); 0: none
    std::int64_t removed_ms = 0;   // 0: still in the torch
    std::string removed_by, removal_reason;
    std::int64_t cuts = 0; // completed cuts
    std::int64_t pierces = 0;
    std::int64_t arc_on_ms = 0;
    double cut_length_mm = 0;
    double arcOnS() const { return static_cast<double>(arc_on_ms) / 1000.0; }
};

struct ConsumableTotals {
    std::int64_t sets = 0; // installations, the current ones included
    std::int64_t cuts = 0, pierces = 0, arc_on_ms = 0;
    double cut_length_mm = 0;
};

// The expected life of a set; 0 = unknown (the chart's source does not give it).
struct ConsumableLife {
    std::int64_t pierces = 0;
    double arc_s = 0;
};
// From the chart's life_pierces and life_arc_minutes.
ConsumableLife consumableLifeOf(const CutChart& chart);

inline constexpr int kWearWarningPercent = 90;
inline constexpr int kWearAlarmPercent = 100;

enum class WearLevel : std::uint8_t { Ok, Warning, Alarm };
enum class WearLimit : std::uint8_t { None, Pierces, ArcTime }; // None: no life known
const char* toString(WearLevel level);                          // "ok", "warning", "alarm"

struct ConsumableWear {
    double fraction = 0; // the larger of the known limits' fractions (1 = the expected life)
    WearLevel level = WearLevel::Ok;
    WearLimit limit = WearLimit::None; // the limit the fraction is of
    // "pierces: 900 of 1000 (90 %)", "arc-on time: 45.0 of 50.0 min (90 %)", "expected life
    // unknown".
    std::string text;
};
// Warning from 90 %, alarm from 100 %, of the limit used most; an unknown life never warns.
ConsumableWear consumableWear(const ConsumableCounters& c, const ConsumableLife& life);

// Where core and the app keep the counters. Every call is I/O (a database write waits for the
// disk): never from the engine's cycle. Implementations throw on a store that cannot be read or
// written (devices: RecordError) and std::invalid_argument on negative or non-finite figures.
class ConsumableLedger {
  public:
    virtual ~ConsumableLedger() = default;
    // The set in the torch now; zeros (id 0) for a set that has no cut recorded yet.
    virtual ConsumableCounters current(const ConsumableSetId& set) const = 0;
    // One COMPLETED cut (pierce to arc off), once: durable when it returns (the counters after
    // it). A set not yet in the ledger is installed by its first cut.
    virtual ConsumableCounters recordCut(const ConsumableSetId& set, std::int64_t pierces,
                                         double arc_s, double length_mm) = 0;
    // The operator fitted new consumables: the current set's counters are closed as history
    // (who, when, why) and a new installation starts from zero. Logged in the audit trail with
    // the counts at replacement. Returns the new set's counters.
    virtual ConsumableCounters replace(const ConsumableSetId& set, const std::string& user,
                                       const std::string& reason) = 0;
    // Every installation of the set, oldest first; the current one (removed_ms 0) last.
    virtual std::vector<ConsumableCounters> history(const ConsumableSetId& set) const = 0;
    // Over every set and installation.
    virtual ConsumableTotals totals() const = 0;
};

// The audit trail's event for a replacement (core/record/audit.h's list does not name it yet).
inline constexpr const char* kConsumablesReplacedEvent = "consumables replaced";

} // namespace cutcell
