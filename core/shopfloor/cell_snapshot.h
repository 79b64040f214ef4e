#pragma once
// What the cell tells the shop floor, as one value: the app fills a CellSnapshot from the
// engine's telemetry, the run model and the job queue (on the GUI thread or a timer thread)
// and hands it to the shop-floor link, which compares it with the last one and publishes what
// changed. Plain data without Qt and without any notion of MQTT or Sparkplug: the link
// (devices/shopfloor) decides the metric names and types, core only says what it knows.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cutcell::shopfloor {

struct AxisSnapshot {
    std::string name;           // "J1", "chuck", "carriage" (the machine's own axis name)
    std::string unit;           // "deg" or "mm": published as the metrics' engUnit
    double position = 0;        // actual position, in unit
    double following_error = 0; // set-point minus actual, in unit
};

// The figures of the last finished run (published once, when the run ends).
struct LastRunFigures {
    double cycle_time_s = 0;
    double tracking_rms = 0; // in error_unit
    double tracking_max = 0; // largest |error|, in error_unit
    std::string error_unit;  // "deg", "mm"
    std::string outcome;     // "completed", "stopped by the operator", "fault: ..."
};

// The consumable counters, where the machine has them (a torch: pierces and arc-on time).
struct ConsumableCounters {
    std::uint64_t pierces = 0;
    double arc_on_s = 0;
};

struct CellSnapshot {
    std::string machine_id;          // "pipe_robot"
    std::string machine_name;        // "Pipe-cutting robot"
    std::string state;               // the engine's state word: "Idle", "Running", "Paused", ...
    std::string job_name;            // empty: no job loaded
    double progress = 0;             // 0..1 of the running job
    std::uint64_t pieces_made = 0;   // whole pieces (or strokes, pierces) the run has made
    std::string made;                // what was made, in the machine's words ("3 pieces, 1250 mm")
    std::vector<std::string> alarms; // the active alarms, one line each
    double override_fraction = 1;    // feed override, 1 = 100 %
    std::vector<AxisSnapshot> axes;
    std::optional<LastRunFigures> last_run;
    std::optional<ConsumableCounters> consumables;
    std::uint32_t queue_length = 0; // jobs waiting in the job queue (from any source)
};

} // namespace cutcell::shopfloor
