// cutcell-cli bench: speed figures of each machine's core (MachineModule::addBenchFigures), of
// the motion engine on the job's machine (the default job unless --job) and of the CAN bus.
// Printed, never asserted: shared machines make timed assertions flaky.
#include "cli_commands.h"
#ifdef CUTCELL_HAVE_DEVICES
#include "bench_can.h"
#include "bench_engine.h"
#include "realtime_options.h"
#endif

#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/machine_registry.h"

#include <cstdio>

namespace cutcell::cli {

int runBench(const BenchOptions& o) {
    const bool asJson = o.json;
    const bool quick = o.quick;
    Job job = defaultJob();
    const std::string& jobFile = o.job;
    int code = kOk;
    if (!jobFile.empty() && !loadJobArg(jobFile, job, &code)) return code;
    job.sim.period_s = 0.001;
#ifdef CUTCELL_HAVE_DEVICES
    const RealtimeSettings& realtime =
        o.rt; // --rt-priority, --rt-cpu, --rt-dma-latency, --no-mlock
#endif

    json::Object out;
    // Each machine's own figures (the pipe robot's IK and simulation speed first).
    for (const MachineModule* m : machines())
        m->addBenchFigures(quick, out);
#ifdef CUTCELL_HAVE_DEVICES
    if (!o.no_engine) benchEngine(job, quick, realtime, out);
#endif

#ifdef CUTCELL_HAVE_DEVICES
    if (!o.no_can) benchCan(out, quick);
#endif
    const json::Value doc(std::move(out));
    if (asJson) {
        std::fputs(json::write(doc).c_str(), stdout);
    } else {
        for (const auto& [k, v] : doc.asObject())
            std::printf("%-28s %.6g\n", k.c_str(), v.asNumber());
    }
    return kOk;
}

} // namespace cutcell::cli
