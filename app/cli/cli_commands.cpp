#include "cli_commands.h"

#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machine/machine_registry.h"
#include "core/machines/pipe_robot/plan_csv.h"
#include "core/trajectory/cut_planner.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace cutcell::cli {

std::string option(const Args& args, const std::string& name) {
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == name && i + 1 < args.size()) return args[i + 1];
        if (args[i].rfind(name + "=", 0) == 0) return args[i].substr(name.size() + 1);
    }
    return {};
}

bool flag(const Args& args, const std::string& name) {
    for (const auto& a : args)
        if (a == name) return true;
    return false;
}

std::vector<std::string> positionals(const Args& args,
                                     const std::vector<std::string>& valueOptions) {
    std::vector<std::string> out;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a.rfind("--", 0) == 0) {
            for (const auto& o : valueOptions)
                if (a == o) ++i;
            continue;
        }
        out.push_back(a);
    }
    return out;
}

bool loadJobArg(const Args& args, const std::vector<std::string>& valueOptions, Job& job,
                int* code) {
    const auto pos = positionals(args, valueOptions);
    if (pos.empty()) {
        std::fprintf(stderr, "cutcell-cli: missing JOB file argument\n");
        *code = kUsage;
        return false;
    }
    try {
        job = loadJobFile(pos.front());
        return true;
    } catch (const JobError& e) {
        std::fprintf(stderr, "invalid job: %s\n", e.what());
        *code = std::filesystem::exists(pos.front()) ? kInvalidJob : kFailure;
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

int runValidate(const Args& args) {
    Job job;
    int code = kOk;
    if (!loadJobArg(args, {}, job, &code)) return code;
    const MachineModule* module = nullptr;
    MachinePlan plan;
    if (!planJob(job, {}, &module, &plan, &code)) return code;
    std::printf("job '%s' is valid: %s, %s\n", job.name.c_str(), module->id().c_str(),
                plan.summary.c_str());
    if (!plan.ok()) {
        std::fprintf(stderr, "%s\n", plan.problem.c_str());
        return kUnreachable;
    }
    return kOk;
}

int runPlan(const Args& args) {
    Job job;
    int code = kOk;
    if (!loadJobArg(args, {"--out"}, job, &code)) return code;
    const std::string out = option(args, "--out");
    if (out.empty()) {
        std::fprintf(stderr, "cutcell-cli plan: --out DIR is required\n");
        return kUsage;
    }
    const MachineModule* module = nullptr;
    MachinePlan plan;
    if (!planJob(job, {}, &module, &plan, &code)) return code;
    if (!plan.ok()) {
        std::fprintf(stderr, "%s\n", plan.problem.c_str());
        return kUnreachable;
    }
    try {
        std::filesystem::create_directories(out);
        for (const ExportInfo& e : module->exports()) {
            if (!e.plan_file) continue;
            const std::string file = (std::filesystem::path(out) / e.default_name).string();
            const std::string text = module->exportFile(e.id, job, plan);
            writeFileAtomically(file, text);
            std::printf("wrote %s (%s, %zu bytes)\n", file.c_str(), e.title.c_str(), text.size());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cutcell-cli plan: %s\n", e.what());
        return kFailure;
    }
    return kOk;
}

int runSimulate(const Args& args) {
    Job job;
    int code = kOk;
    const std::vector<std::string> valueOptions{"--report",     "--method",        "--devices",
                                                "--can-plugin", "--can-interface", "--period-ms",
                                                "--clock"};
    if (!loadJobArg(args, valueOptions, job, &code)) return code;
    const MachineModule& module = machineFor(job);
    if (const std::string method = option(args, "--method"); !method.empty()) {
        std::string error;
        if (!module.setVariant(job, method, &error)) {
            std::fprintf(stderr, "cutcell-cli simulate: %s\n", error.c_str());
            return kUsage;
        }
    }
    const MachineModule* m = nullptr;
    MachinePlan plan;
    if (!planJob(job, {}, &m, &plan, &code)) return code;
    if (!plan.ok()) {
        std::fprintf(stderr, "%s\n", plan.problem.c_str());
        return kUnreachable;
    }
    const std::string devices = option(args, "--devices");
    if (!devices.empty() && devices != "simulated" && devices != "canopen") {
        std::fprintf(stderr, "--devices = \"%s\" is not one of \"simulated\", \"canopen\"\n",
                     devices.c_str());
        return kUsage;
    }
    if (devices == "canopen" || (devices.empty() && job.devices.kind == DeviceKind::CanOpen)) {
        std::string why;
        if (!module.supportsCanOpen(&why)) {
            std::fprintf(stderr, "cutcell-cli simulate --devices canopen: %s\n", why.c_str());
            return kInvalidJob;
        }
#ifdef CUTCELL_HAVE_DEVICES
        // The offline CAN cut follows the robot's CutPlan (the only CAN machine so far).
        // TODO(modules): run it from plan.program like the engine path, for every machine.
        return runSimulateCan(job, *static_cast<const CutPlan*>(plan.data.get()), args);
#else
        std::fprintf(stderr,
                     "cutcell-cli simulate: this build has no CAN devices (devices/ not built)\n");
        return kFailure;
#endif
    }
    std::string text, table, why;
    if (!module.offlineReport(job, plan, &text, &table, &why)) {
        std::fprintf(stderr, "cutcell-cli simulate: %s\n", why.c_str());
        return kUsage;
    }
    const std::string reportFile = option(args, "--report");
    if (const int rc = emitReport(reportFile, text, "simulate"); rc != kOk || reportFile.empty())
        return rc;
    std::printf("report written to %s\n%s", reportFile.c_str(), table.c_str());
    return kOk;
}

} // namespace cutcell::cli
