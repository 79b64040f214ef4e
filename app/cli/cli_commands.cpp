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

bool loadJobArg(const std::string& file, Job& job, int* code) {
    try {
        job = loadJobFile(file);
        return true;
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

void printUnreachable(const CutPlan& plan) {
    std::fprintf(stderr, "path not reachable (%s method): %s\n", toString(plan.method),
                 plan.problem.c_str());
}

} // namespace

int runValidate(const ValidateOptions& o) {
    Job job;
    int code = kOk;
    if (!loadJobArg(o.job, job, &code)) return code;
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

int runPlan(const PlanOptions& o) {
    Job job;
    int code = kOk;
    if (!loadJobArg(o.job, job, &code)) return code;
    const std::string& out = o.out;
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

int runSimulate(const SimulateOptions& o) {
    Job job;
    int code = kOk;
    if (!loadJobArg(o.job, job, &code)) return code;
    if (job.machine != "pipe_robot_6axis") {
        std::fprintf(stderr,
                     "cutcell-cli simulate: the report is for the pipe robot; machine \"%s\" "
                     "runs in the engine: cutcell-cli run JOB\n",
                     job.machine.c_str());
        return kUsage;
    }
    // main.cpp has checked --method and --devices against their choices.
    if (o.method == "static_pipe")
        job.method = CutMethod::StaticPipe;
    else if (o.method == "rotating_pipe")
        job.method = CutMethod::RotatingPipe;
    const CutPlan plan = planCut(job);
    if (!plan.reachable) {
        printUnreachable(plan);
        return kUnreachable;
    }
    const std::string& devices = o.devices.devices;
    if (devices == "canopen" || (devices.empty() && job.devices.kind == DeviceKind::CanOpen)) {
#ifdef CUTCELL_HAVE_DEVICES
        return runSimulateCan(job, plan, o);
#else
        std::fprintf(stderr,
                     "cutcell-cli simulate: this build has no CAN devices (devices/ not built)\n");
        return kFailure;
#endif
    }
    const TrackingReport report = simulateCut(job, plan);
    const std::string text = json::write(reportToJson(report));
    const std::string& reportFile = o.report;
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
