#include "cli_commands.h"

#include "core/io/plan_csv.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/sim/cut_simulation.h"
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

void printUnreachable(const CutPlan& plan) {
    std::fprintf(stderr, "path not reachable (%s method): %s\n", toString(plan.method),
                 plan.problem.c_str());
}

} // namespace

int runValidate(const Args& args) {
    Job job;
    int code = kOk;
    if (!loadJobArg(args, {}, job, &code)) return code;
    if (job.machine == "profile_cutter_2axis") return runProfileValidate(job);
    const CutPlan plan = planCut(job);
    std::printf("job '%s' is valid: %s method, cut %s, %.2f mm at %.2f mm/s (%.2f s)\n",
                job.name.c_str(), toString(job.method), toString(job.cut.target), plan.length_mm,
                job.cut.speed_mm_s, plan.cut_time_s);
    if (!plan.reachable) {
        printUnreachable(plan);
        return kUnreachable;
    }
    std::printf("every point is reachable; largest torch tilt into the joint-1 plane: %.3f deg\n",
                plan.max_deviation_deg);
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
    if (job.machine == "profile_cutter_2axis") return runProfilePlan(job, out);
    const CutPlan plan = planCut(job);
    if (!plan.reachable) {
        printUnreachable(plan);
        return kUnreachable;
    }
    try {
        std::filesystem::create_directories(out);
        const std::string pathFile = (std::filesystem::path(out) / "path.csv").string();
        const std::string jointsFile = (std::filesystem::path(out) / "joints.csv").string();
        writeFileAtomically(pathFile, pathCsv(plan));
        writeFileAtomically(jointsFile, jointsCsv(plan, job.sim.period_s));
        std::printf("wrote %s (%zu points) and %s (%.3f s at %.4f s)\n", pathFile.c_str(),
                    plan.knots.size(), jointsFile.c_str(), plan.cut_time_s, job.sim.period_s);
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
    if (job.machine != "pipe_robot_6axis") {
        std::fprintf(stderr,
                     "cutcell-cli simulate: the report is for the pipe robot; machine \"%s\" "
                     "runs in the engine: cutcell-cli run JOB\n",
                     job.machine.c_str());
        return kUsage;
    }
    const std::string method = option(args, "--method");
    if (method == "static_pipe")
        job.method = CutMethod::StaticPipe;
    else if (method == "rotating_pipe")
        job.method = CutMethod::RotatingPipe;
    else if (!method.empty()) {
        std::fprintf(stderr, "--method = \"%s\" is not one of \"static_pipe\", \"rotating_pipe\"\n",
                     method.c_str());
        return kUsage;
    }
    const CutPlan plan = planCut(job);
    if (!plan.reachable) {
        printUnreachable(plan);
        return kUnreachable;
    }
    const std::string devices = option(args, "--devices");
    if (!devices.empty() && devices != "simulated" && devices != "canopen") {
        std::fprintf(stderr, "--devices = \"%s\" is not one of \"simulated\", \"canopen\"\n",
                     devices.c_str());
        return kUsage;
    }
    if (devices == "canopen" || (devices.empty() && job.devices.kind == DeviceKind::CanOpen)) {
#ifdef CUTCELL_HAVE_DEVICES
        return runSimulateCan(job, plan, args);
#else
        std::fprintf(stderr,
                     "cutcell-cli simulate: this build has no CAN devices (devices/ not built)\n");
        return kFailure;
#endif
    }
    const TrackingReport report = simulateCut(job, plan);
    const std::string text = json::write(reportToJson(report));
    const std::string reportFile = option(args, "--report");
    if (const int rc = emitReport(reportFile, text, "simulate"); rc != kOk || reportFile.empty())
        return rc;
    std::printf("%s method, %.1f s simulated at %.4f s: report written to %s\n",
                report.method.c_str(), report.simulated_s, job.sim.period_s, reportFile.c_str());
    std::printf("%-16s %14s %14s\n", "axis", "max |e| (deg)", "rms (deg)");
    for (int i = 0; i < kAxisCount; ++i)
        std::printf("%-16s %14.6f %14.6f\n",
                    i == 0 ? "0 chuck" : ("" + std::to_string(i) + " arm").c_str(),
                    report.joints[static_cast<size_t>(i)].max_abs_deg,
                    report.joints[static_cast<size_t>(i)].rms_deg);
    std::printf("tip error (mm), base frame: x %.6f  y %.6f  z %.6f\n",
                report.cartesian_max_abs_mm.x(), report.cartesian_max_abs_mm.y(),
                report.cartesian_max_abs_mm.z());
    return kOk;
}

} // namespace cutcell::cli
