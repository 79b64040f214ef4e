#pragma once
// What each cutcell-cli command was given on its command line, filled by the CLI11 parser of
// main.cpp (which has already refused unknown options and checked every value against its
// range). The commands read these structs; none of them looks at argv.
#include "can_run.h"
#include "core/engine/realtime_thread.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cutcell::cli {

struct ValidateOptions {
    std::string job;
};

struct PlanOptions {
    std::string job;
    std::string out; // directory for the machine's plan files
};

// --devices and the CANopen overrides of simulate and run.
struct DeviceOptions {
    std::string devices; // "", "simulated" or "canopen" (empty: the job's devices section)
    CanRunOptions can;   // --can-plugin, --can-interface, --period-ms, --clock, --drivesim
};

struct SimulateOptions {
    std::string job;
    std::string report; // empty: the report goes to stdout
    std::string method; // "", "static_pipe" or "rotating_pipe" (empty: the job's method)
    DeviceOptions devices;
};

struct BenchOptions {
    std::string job; // empty: the default job
    bool json = false;
    bool quick = false;
    bool no_engine = false;
    bool no_can = false;
    RealtimeSettings rt; // --rt-priority, --rt-cpu, --rt-dma-latency, --no-mlock
};

struct ExportOptions {
    std::string job;
    // One file per export id of the machine's module; empty: not written.
    std::string gcode, template_svg, template_pdf, path_csv, joints_csv;
    std::string paper = "single"; // cutting templates: "single", "A4", "A3"
};

struct MachinesOptions {
    bool json = false;
};

// cutcell-cli fk / ik (arm machines): the arm, and the joints (deg) or the torch pose.
struct CompareOptions {
    std::string job;
    std::string out; // default: ./compare-<job stem>
};

struct KinematicsOptions {
    std::string job;
    std::string arm;
    std::string values; // comma-separated numbers (C locale)
};

// cutcell-cli tune: the job, where the tuned job goes (empty: nowhere, the gains are printed)
// and the closed-loop time constant (0: the machine's default).
struct TuneCommandOptions {
    std::string job;
    std::string out;
    double tau_c_ms = 0;
};

// cutcell-cli materials: the cut-chart table in use (the user's, else the shipped one; or
// --file), listed or one row picked for a process, material, consumable set and thickness; or
// one edit of it (--set, --add-row, --remove-row), written back atomically to the user's table
// (or --file).
struct MaterialsOptions {
    std::string file;
    bool json = false;
    std::vector<std::string> pick;       // PROCESS MATERIAL CONSUMABLE THICKNESS_MM
    std::vector<std::string> set;        // PROCESS MATERIAL CONSUMABLE THICKNESS_MM FIGURE VALUE
    std::vector<std::string> add_row;    // PROCESS MATERIAL CONSUMABLE THICKNESS_MM FIGURE=VALUE...
    std::vector<std::string> remove_row; // PROCESS MATERIAL CONSUMABLE THICKNESS_MM
};

// cutcell-cli shopfloor: the edge node headless (issue 26).
struct ShopfloorOptions {
    std::string config;    // the shop-floor configuration file
    std::string run;       // a job to run on the simulated rig while publishing ("": idle cell)
    bool realtime = false; // the run paced by the wall clock (else as fast as it computes)
    bool quiet = false;
    double linger_s = 0; // stay connected this long after the run (idle: 0 = until a signal)
};

// cutcell-cli bench-shopfloor: the link's figures against a local broker (issue 26).
struct BenchShopfloorOptions {
    std::optional<int> cells;  // simulated cells, each its own edge node (default 1)
    double seconds = 30;       // the measuring window
    bool outage = false;       // the engine's run with the broker killed and restarted instead
    std::optional<int> rounds; // --outage: rounds of the three runs, interleaved (default 1)
    std::string job;           // --outage: the job run (default: the default job)
    bool json = false;
};

struct UpgradeOptions {
    std::string job; // the old (schema 1) job file
    std::string out; // the schema-2 file, written atomically
};

// cutcell-cli import-<name> (one command per registered importer).
struct ImportOptions {
    std::string importer; // the importer's name ("dstv")
    std::string file;     // the file to import
    std::string out;      // the job file, written atomically
};

struct RunOptions {
    std::string job;
    bool realtime = false;
    bool quiet = false;
    std::string report; // empty: the report goes to stdout
    std::string runs;   // empty: the job's engine.runs_dir
    std::string record; // the production record (SQLite file or PostgreSQL URL) to add the run to;
                        // empty: none
    DeviceOptions devices;
    RealtimeSettings rt; // --rt-priority, --rt-cpu, --rt-dma-latency, --no-mlock
};

// history: the production record's runs.
struct HistoryOptions {
    std::string db;    // empty: RunRecordStore::defaultPath()
    std::string since; // YYYY-MM-DD (UTC), empty: every run
    std::string machine, outcome;
    bool json = false, csv = false;
};

// users: the station's users (user levels) in the production record.
struct UsersOptions {
    std::string action; // list, add, remove, passwd, level
    std::string name;
    std::string level; // add, level: operator, setter, engineer, administrator
    std::string admin; // the administrator who authorises a change (password on stdin)
    std::string db;    // empty: the default production record
};

// audit: the audit trail of the production record.
struct AuditOptions {
    std::string db;
    std::string since; // YYYY-MM-DD (UTC)
    bool json = false, csv = false;
};

struct DriveSimOptions {
    std::string job;                         // empty: the default job
    std::string nodes_text;                  // --nodes as given (empty: the job's node ids)
    std::vector<int> nodes;                  // --nodes expanded, ids 1..127
    std::string plugin;                      // empty: the simulator's default
    std::string interface;                   // empty: the simulator's default
    double duration_s = 0;                   // 0: until SIGINT/SIGTERM
    std::optional<int> fault_node;           // empty: the first simulated node
    std::optional<std::uint16_t> fault_code; // EMCY code 0x0001..0xFFFF
    std::optional<double> fault_after_s;     // times in s, [0, 1e6]
    std::optional<double> heartbeat_stop_after_s;
    std::optional<double> following_error_after_s;
    std::optional<std::uint16_t> refuse_object; // SDO writes to it aborted
};

} // namespace cutcell::cli
