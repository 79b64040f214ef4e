// cutcell-cli tune: the machine's controller gains from its model (the pipe robot: SIMC on each
// axis, core/machines/pipe_robot/pipe_robot_tuning.h) through MachineModule::tuneControllers.
// It prints the gains with the figures they come from. The job file is not touched: the tuned
// job is written only where --out says (atomically; --out JOB replaces the job itself), so that
// a look at the gains never changes a job behind the user's back.
// Exit: 0 ok, 1 I/O, 2 invalid job, 3 the cut cannot be planned (the tuning needs its poses),
// 64 a machine without tuning.
#include "cli_commands.h"

#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"

#include <cstdio>

namespace cutcell::cli {

int runTune(const TuneCommandOptions& o) {
    Job job;
    int code = kOk;
    if (!loadJobArg(o.job, job, &code)) return code;
    const MachineModule& module = machineFor(job);
    TuneOptions options;
    options.tau_c_s = o.tau_c_ms * 1e-3;
    std::string text;
    const Outcome done = module.tuneControllers(job, options, &text);
    if (!done.ok()) {
        std::fprintf(stderr, "cutcell-cli tune: %s\n", done.message.c_str());
        if (done.key == "machine.kind") return kUsage;
        return done.key.empty() ? kUnreachable : kInvalidJob;
    }
    std::fputs(text.c_str(), stdout);
    if (o.out.empty()) {
        std::printf("not written: --out FILE writes the job with these gains (--out %s replaces "
                    "it)\n",
                    o.job.c_str());
        return kOk;
    }
    try {
        saveJobFile(job, o.out);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cutcell-cli tune: %s\n", e.what());
        return kFailure;
    }
    std::printf("wrote %s (controller[] gains tuned)\n", o.out.c_str());
    return kOk;
}

} // namespace cutcell::cli
