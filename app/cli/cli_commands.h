#pragma once
// The sub-commands of cutcell-cli. Exit codes: 0 ok, 1 I/O or internal error, 2 invalid job,
// 3 path not reachable, 64 usage.
#include <string>
#include <vector>

namespace cutcell {
struct Job;
struct CutPlan;
} // namespace cutcell

namespace cutcell::cli {

enum ExitCode { kOk = 0, kFailure = 1, kInvalidJob = 2, kUnreachable = 3, kUsage = 64 };

using Args = std::vector<std::string>;

int runValidate(const Args& args);
int runPlan(const Args& args);
int runSimulate(const Args& args);
int runBench(const Args& args);
int runExport(const Args& args);
int runRun(const Args& args);      // run_command.cpp (needs CutCell::devices)
int runDriveSim(const Args& args); // drivesim_command.cpp
int runSimulateCan(const Job& job, const CutPlan& plan, const Args& args); // can_run.cpp

// Value of "--name VALUE" (or "--name=VALUE"); empty when absent.
std::string option(const Args& args, const std::string& name);
bool flag(const Args& args, const std::string& name);
// Positional arguments (not options or their values).
std::vector<std::string> positionals(const Args& args,
                                     const std::vector<std::string>& valueOptions);
// Loads the job named by the first positional argument; on failure prints the reason and sets
// *code (kUsage: no argument, kInvalidJob: a bad job file, kFailure: it cannot be read).
bool loadJobArg(const Args& args, const std::vector<std::string>& valueOptions, Job& job,
                int* code);
// Prints a JSON report on stdout when reportFile is empty, else writes it atomically there.
// Returns kOk, or kFailure with the reason on stderr ("cutcell-cli <command>: ...").
int emitReport(const std::string& reportFile, const std::string& text, const char* command);

} // namespace cutcell::cli
