// cutcell-cli export, and plan/validate for the 2-axis profile cutter (seed 002).
#include "cli_commands.h"

#include "core/io/gcode_export.h"
#include "core/io/profile_csv.h"
#include "core/io/template_pdf.h"
#include "core/io/template_svg.h"
#include "core/job/job_io.h"
#include "core/machines/profile_cutter.h"
#include "core/machines/stepper_schedule.h"

#include <cstdio>
#include <filesystem>

namespace cutcell::cli {
namespace {

constexpr const char* kProfileMachine = "profile_cutter_2axis";

void write(const std::string& path, const std::string& text, const char* what) {
    writeFileAtomically(path, text);
    std::printf("wrote %s (%s, %zu bytes)\n", path.c_str(), what, text.size());
}

} // namespace

int runProfileValidate(const Job& job) {
    const ProfileCut cut = computeProfileCut(job);
    const PulseSchedule sch = buildPulseSchedule(cut, job.profile_cutter, job.cut.speed_mm_s);
    std::printf("job '%s' is valid: %s, cut %s, %zu steps/rev, developed length %.2f mm at %.2f "
                "mm/s (%.2f s)\n",
                job.name.c_str(), kProfileMachine, toString(job.cut.target), cut.points.size(),
                sch.developed_length_mm, job.cut.speed_mm_s, sch.total_time_s);
    std::printf("largest pulse rates: X %.0f Hz, A %.0f Hz (limit %.0f Hz)\n", sch.max_x_rate_hz,
                sch.max_a_rate_hz, job.profile_cutter.max_pulse_rate_hz);
    if (!sch.problem.empty()) {
        std::fprintf(stderr, "not feasible: %s\n", sch.problem.c_str());
        return kUnreachable;
    }
    if (const std::string travel = travelProblem(job, cut); !travel.empty()) {
        std::fprintf(stderr, "not feasible: %s\n", travel.c_str());
        return kUnreachable;
    }
    return kOk;
}

int runProfilePlan(const Job& job, const std::string& outDir) {
    const ProfileCut cut = computeProfileCut(job);
    const PulseSchedule sch = buildPulseSchedule(cut, job.profile_cutter, job.cut.speed_mm_s);
    if (!sch.problem.empty()) {
        std::fprintf(stderr, "not feasible: %s\n", sch.problem.c_str());
        return kUnreachable;
    }
    try {
        std::filesystem::create_directories(outDir);
        write((std::filesystem::path(outDir) / "path.csv").string(), profilePathCsv(cut, sch),
              "profile cutter path");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cutcell-cli plan: %s\n", e.what());
        return kFailure;
    }
    return kOk;
}

int runExport(const ExportOptions& o) {
    Job job;
    int code = kOk;
    if (!loadJobArg(o.job, job, &code)) return code;
    const std::string &gcode = o.gcode, &svg = o.template_svg, &pdf = o.template_pdf,
                      &csv = o.path_csv;
    if (gcode.empty() && svg.empty() && pdf.empty() && csv.empty()) {
        std::fprintf(stderr,
                     "cutcell-cli export: give at least one of --gcode FILE, --template-svg FILE, "
                     "--template-pdf FILE, --path-csv FILE\n");
        return kUsage;
    }
    // The template is pure geometry (any job); G-code and pulses need the 2-axis machine.
    if ((!gcode.empty() || !csv.empty()) && job.machine != kProfileMachine) {
        std::fprintf(stderr,
                     "cutcell-cli export: --gcode and --path-csv need machine = \"%s\"; this job "
                     "has \"%s\"\n",
                     kProfileMachine, job.machine.c_str());
        return kInvalidJob;
    }
    try {
        if (!gcode.empty() || !csv.empty()) {
            const ProfileCut cut = computeProfileCut(job);
            if (const std::string travel = travelProblem(job, cut); !travel.empty()) {
                std::fprintf(stderr, "cutcell-cli export: %s\n", travel.c_str());
                return kUnreachable;
            }
            if (!gcode.empty()) {
                GcodeStats st;
                const std::string text = profileGcode(job, cut, &st);
                write(gcode, text, "LinuxCNC G-code, X/A");
                std::printf("  %zu moves, developed length %.3f mm, %.2f s at %.3f mm/s\n",
                            st.moves, st.length_mm, st.time_s, job.cut.speed_mm_s);
            }
            if (!csv.empty()) {
                const PulseSchedule sch =
                    buildPulseSchedule(cut, job.profile_cutter, job.cut.speed_mm_s);
                if (!sch.problem.empty())
                    std::fprintf(stderr, "warning: %s\n", sch.problem.c_str());
                write(csv, profilePathCsv(cut, sch), "profile cutter path");
            }
        }
        if (!svg.empty() || !pdf.empty()) {
            const TemplateDrawing drawing = buildTemplate(job);
            if (!svg.empty()) write(svg, templateSvg(drawing), "cutting template, SVG 1:1");
            if (!pdf.empty()) write(pdf, templatePdf(drawing), "cutting template, PDF 1:1");
            std::printf("  template %.1f x %.1f mm, circumference %.3f mm\n", drawing.width_mm,
                        drawing.height_mm, drawing.circumference_mm);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cutcell-cli export: %s\n", e.what());
        return kFailure;
    }
    return kOk;
}

} // namespace cutcell::cli
