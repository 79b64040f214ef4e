#pragma once
// The sub-commands of cutcell-cli. Exit codes: 0 ok, 1 I/O or internal error, 2 invalid job,
// 3 path not reachable, 64 usage.
#include "cli_options.h"

#include <string>

namespace cutcell {
struct Job;
struct MachinePlan;
class MachineModule;
} // namespace cutcell

namespace cutcell::cli {

enum ExitCode { kOk = 0, kFailure = 1, kInvalidJob = 2, kUnreachable = 3, kUsage = 64 };

int runValidate(const ValidateOptions& o);
int runPlan(const PlanOptions& o);
int runSimulate(const SimulateOptions& o);
int runBench(const BenchOptions& o);
int runExport(const ExportOptions& o);
int runMachines(const MachinesOptions& o);   // machines_command.cpp
int runUpgrade(const UpgradeOptions& o);     // machines_command.cpp
int runTune(const TuneCommandOptions& o);    // tune_command.cpp
int runMaterials(const MaterialsOptions& o); // materials_command.cpp
int runFk(const KinematicsOptions& o);       // kinematics_command.cpp
int runCompare(const CompareOptions& o);     // compare_command.cpp
int runIk(const KinematicsOptions& o);       // kinematics_command.cpp
int runImport(const ImportOptions& o);       // import_command.cpp
int runRun(const RunOptions& o);             // run_command.cpp (needs CutCell::devices)
int runShopfloor(const ShopfloorOptions& o); // shopfloor_command.cpp (needs CutCell::shopfloor)
int runBenchShopfloor(const BenchShopfloorOptions& o); // bench_shopfloor.cpp (needs a broker)
int runDriveSim(const DriveSimOptions& o);             // drivesim_command.cpp
int runHistory(const HistoryOptions& o); // history_command.cpp (needs CutCell::devices)
int runUsers(const UsersOptions& o);     // users_command.cpp (needs CutCell::devices)
int runAudit(const AuditOptions& o);     // users_command.cpp (needs CutCell::devices)
// simulate --devices canopen: the program through the engine on the machine's CAN cell.
int runSimulateCan(const Job& job, const MachineModule& module, const MachinePlan& plan,
                   const SimulateOptions& o); // can_run.cpp

// The user's cut-chart table ($XDG_DATA_HOME/cutcell/cut_charts.json) becomes the one every job
// is planned with, as in the GUI; one that cannot be used is said on stderr and the shipped
// table stays in use.
void installUserCutCharts();

// Loads the job file; on failure prints the reason and sets *code (kInvalidJob: a bad job
// file, kFailure: it cannot be read).
bool loadJobArg(const std::string& file, Job& job, int* code);
// Prints a JSON report on stdout when reportFile is empty, else writes it atomically there.
// Returns kOk, or kFailure with the reason on stderr ("cutcell-cli <command>: ...").
int emitReport(const std::string& reportFile, const std::string& text, const char* command);

} // namespace cutcell::cli
