// cutcell-cli: headless planning, simulation and benchmarks over the CutCell core.
#include "cli_commands.h"

#include <cstdio>
#include <cstring>

namespace {

const char* kUsageText = R"(cutcell-cli - headless CutCell

usage:
  cutcell-cli validate JOB                  check a job file
  cutcell-cli plan JOB --out DIR            write DIR/path.csv and DIR/joints.csv
  cutcell-cli simulate JOB [--report FILE]  simulate the cut, print/write the JSON report
  cutcell-cli bench [--json] [--quick] [RT]  measure speed figures, the host's wake-up
                                            latency and what the engine adds to it
  cutcell-cli export JOB [--gcode FILE] [--template-svg FILE] [--template-pdf FILE] [--path-csv FILE]
                                            profile cutter G-code (LinuxCNC X/A), 1:1 cutting
                                            template, path with stepper pulses
  cutcell-cli run JOB [--realtime] [--report FILE] [--runs DIR] [--quiet] [RT]
                                            run the job through the motion engine on
                                            simulated drives; writes a run log
     RT (engine thread, real-time clock): [--rt-priority 0-99 (80; 0 = normal scheduler)]
                 [--rt-cpu N] [--rt-dma-latency] [--no-mlock]
  cutcell-cli simulate JOB --devices canopen [--can-plugin P] [--can-interface I]
                 [--period-ms T] [--clock realtime|fast] [--drivesim]
                                            run the cut over CANopen drives (--drivesim: start
                                            simulated drives in-process)
  cutcell-cli drivesim [JOB] [--nodes 1-6] [--plugin P] [--interface I] [--duration S]
                 [--fault-node N] [--fault-code 0xNNNN] [--fault-after S]
                 [--heartbeat-stop-after S] [--following-error-after S]
                                            CiA 402 drive simulator on a CAN bus

exit codes: 0 ok, 1 error, 2 invalid job, 3 path not reachable, 64 usage
)";

} // namespace

int main(int argc, char** argv) {
    using namespace cutcell::cli;
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") ||
        !std::strcmp(argv[1], "help")) {
        std::fputs(kUsageText, argc < 2 ? stderr : stdout);
        return argc < 2 ? kUsage : kOk;
    }
    const std::string cmd = argv[1];
    const Args args(argv + 2, argv + argc);
    if (cmd == "validate") return runValidate(args);
    if (cmd == "plan") return runPlan(args);
    if (cmd == "simulate") return runSimulate(args);
    if (cmd == "bench") return runBench(args);
    if (cmd == "export") return runExport(args);
#ifdef CUTCELL_HAVE_DEVICES
    if (cmd == "run") return runRun(args);
    if (cmd == "drivesim") return runDriveSim(args);
#endif
    std::fprintf(stderr, "cutcell-cli: unknown command '%s'\n\n%s", cmd.c_str(), kUsageText);
    return ExitCode::kUsage;
}
