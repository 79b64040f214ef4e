#include "cli_commands.h"

#include "core/job/file_set.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/machine_registry.h"
#include "core/process/cut_chart_library.h"
#include "core/process/process_spec.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace cutcell::cli {

void installUserCutCharts() {
    try {
        CutChartsInUse inUse = loadCutChartsInUse(defaultDataHome());
        if (inUse.user) setActiveCutCharts(std::move(inUse.set));
    } catch (const std::exception& e) {
        std::fprintf(stderr,
                     "cutcell-cli: the user's cut charts are not used (the shipped ones are): %s\n",
                     e.what());
    }
}

bool loadJobArg(const std::string& file, Job& job, int* code) {
    try {
        job = loadJobFile(file);
        return true;
    } catch (const JobFileError& e) {
        std::fprintf(stderr, "cannot read the job: %s\n", e.what());
        *code = kFailure;
        return false;
    } catch (const JobError& e) {
        std::fprintf(stderr, "invalid job: %s\n", e.what());
        *code = std::filesystem::exists(file) ? kInvalidJob : kFailure;
        return false;
    }
}

int emitReport(const std::string& reportFile, const std::string& text, const char* command) {
    if (reportFile.empty()) {
        std::fputs(text.c_str(), stdout);
        return kOk;
    }
    try {
        writeFileAtomically(reportFile, text);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cutcell-cli %s: %s\n", command, e.what());
        return kFailure;
    }
    return kOk;
}

namespace {

// The job's machine module and its plan; false (and *code) when the job cannot be planned.
bool planJob(const Job& job, const std::string& jobText, const MachineModule** module,
             MachinePlan* plan, int* code) {
    *module = &machineFor(job);
    try {
        *plan = (*module)->plan(job, jobText);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "invalid job: %s\n", e.what());
        *code = kInvalidJob;
        return false;
    }
    return true;
}

} // namespace

int runValidate(const ValidateOptions& o) {
    Job job;
    int code = kOk;
    if (!loadJobArg(o.job, job, &code)) return code;
    const MachineModule* module = nullptr;
    MachinePlan plan;
    if (!planJob(job, {}, &module, &plan, &code)) return code;
    if (!plan.ok()) {
        // Well-formed, but the machine cannot make it: never "valid". The plan's summary when
        // it tells more than the reason (the flying saw's summary is the reason itself).
        const std::string& why = plan.outcome.message;
        const bool summaryAdds =
            !plan.summary.empty() && why.find(plan.summary) == std::string::npos;
        std::printf("job '%s' is refused (not feasible): %s%s%s\n", job.name.c_str(),
                    module->id().c_str(), summaryAdds ? ", " : "",
                    summaryAdds ? plan.summary.c_str() : "");
        std::fprintf(stderr, "%s\n", why.empty() ? "not feasible" : why.c_str());
        return kUnreachable;
    }
    std::printf("job '%s' is valid: %s, %s\n", job.name.c_str(), module->id().c_str(),
                plan.summary.c_str());
    return kOk;
}

int runPlan(const PlanOptions& o) {
    Job job;
    int code = kOk;
    if (!loadJobArg(o.job, job, &code)) return code;
    const std::string& out = o.out;
    const MachineModule* module = nullptr;
    MachinePlan plan;
    if (!planJob(job, {}, &module, &plan, &code)) return code;
    if (!plan.ok()) {
        std::fprintf(stderr, "%s\n", plan.outcome.message.c_str());
        return kUnreachable;
    }
    try {
        // The plan's files as one unit: a kill leaves the folder's old set or the new one.
        const std::vector<ExportInfo> exports = module->exports();
        std::vector<FileContents> files;
        std::vector<const ExportInfo*> infos;
        for (const ExportInfo& e : exports) {
            if (!e.plan_file) continue;
            files.push_back({e.default_name, module->exportFile(e.id, job, plan)});
            infos.push_back(&e);
        }
        writeFolderSet(out, files);
        for (size_t i = 0; i < files.size(); ++i)
            std::printf("wrote %s (%s, %zu bytes)\n",
                        (std::filesystem::path(out) / files[i].path).string().c_str(),
                        infos[i]->title.c_str(), files[i].contents.size());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cutcell-cli plan: %s\n", e.what());
        return kFailure;
    }
    return kOk;
}

int runSimulate(const SimulateOptions& o) {
    Job job;
    int code = kOk;
    if (!loadJobArg(o.job, job, &code)) return code;
    const MachineModule& module = machineFor(job);
    // main.cpp has checked --devices against its choices; the module checks --method.
    if (!o.method.empty()) {
        std::string error;
        if (const Outcome variant = module.setVariant(job, o.method); !variant.ok()) {
            std::fprintf(stderr, "cutcell-cli simulate: %s\n", variant.message.c_str());
            return kUsage;
        }
    }
    const std::string& devices = o.devices.devices;
    const bool overCan =
        devices == "canopen" || (devices.empty() && job.devices.kind == DeviceKind::CanOpen);
    if (const Outcome can = module.canOpen(); overCan && !can.ok()) {
        std::fprintf(stderr, "cutcell-cli simulate --devices canopen: %s\n", can.message.c_str());
        return kInvalidJob;
    }
    // Over CAN a --period-ms is the engine's cycle: the plan is made for it.
    if (overCan && o.devices.can.period_s > 0) job.sim.period_s = o.devices.can.period_s;
    const MachineModule* m = nullptr;
    MachinePlan plan;
    if (!planJob(job, {}, &m, &plan, &code)) return code;
    if (!plan.ok()) {
        std::fprintf(stderr, "%s\n", plan.outcome.message.c_str());
        return kUnreachable;
    }
    if (overCan) {
#ifdef CUTCELL_HAVE_DEVICES
        return runSimulateCan(job, module, plan, o);
#else
        std::fprintf(stderr,
                     "cutcell-cli simulate: this build has no CAN devices (devices/ not built)\n");
        return kFailure;
#endif
    }
    std::string text, table;
    const Outcome report = module.offlineReport(job, plan, &text, &table);
    if (report.refused()) {
        std::fprintf(stderr, "cutcell-cli simulate: %s\n", report.message.c_str());
        return kUsage;
    }
    const std::string& reportFile = o.report;
    // A run that did not complete still gets its report, and says why on the way out.
    const int incomplete = report.ok() ? kOk : kFailure;
    if (!report.ok()) std::fprintf(stderr, "cutcell-cli simulate: %s\n", report.message.c_str());
    if (const int rc = emitReport(reportFile, text, "simulate"); rc != kOk || reportFile.empty())
        return rc != kOk ? rc : incomplete;
    std::printf("report written to %s\n%s", reportFile.c_str(), table.c_str());
    return incomplete;
}

} // namespace cutcell::cli
