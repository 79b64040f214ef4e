#pragma once
// Jobs for the profile cutter tests: the shipped example and random valid variations of it.
#include "core/job/job_io.h"
#include "core/machines/profile_cutter/profile_cutter_spec.h"

#include <array>
#include <cctype>
#include <cstdio>
#include <random>
#include <string>

namespace cutcell::test {

// A shell command's standard output, and its wait status in *status (rs274, pdftotext, ...).
inline std::string runCommand(const std::string& cmd, int* status) {
    std::string out;
    FILE* p = ::popen(cmd.c_str(), "r");
    if (!p) return out;
    std::array<char, 4096> buf{};
    size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0)
        out.append(buf.data(), n);
    *status = ::pclose(p);
    return out;
}

// LinuxCNC's interpreter (Debian linuxcnc-uspace), or "" where it is not installed.
inline std::string findRs274() {
    int status = 0;
    std::string path = runCommand("command -v rs274 2>/dev/null", &status);
    while (!path.empty() && std::isspace(static_cast<unsigned char>(path.back())))
        path.pop_back();
    return status == 0 ? path : std::string();
}

// rs274 reading `file`, with HOME set to the file's folder: the interpreter truncates and maps
// $HOME/.tool.mmap, so two at once under one HOME (ctest -j2 runs three rs274 tests) crashed one
// with SIGBUS.
inline std::string runRs274(const std::string& rs274, const std::string& file, int* status) {
    const std::string folder = file.substr(0, file.rfind('/'));
    return runCommand("HOME='" + folder + "' '" + rs274 + "' -g '" + file + "' 2>&1", status);
}

// A plasma process on the shipped chart, its row picked at 3 mm (the shipped charts give no kerf:
// the tests set it as an override).
inline void setPlasmaProcess(Job& job) {
    job.process.used = true;
    job.process.process = CutProcess::Plasma;
    job.process.material = "mild_steel";
    job.process.consumable = "Powermax65/85 45A shielded";
    job.process.thickness_mm = 3.0;
}

inline Job exampleProfileJob() {
    return loadJobFile(std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/profile_cutter_job.json");
}

// A valid profile-cutter job with random pipes, angle and eccentricity (single branch).
inline Job randomProfileJob(std::mt19937& rng, CutTarget target) {
    std::uniform_real_distribution<double> U(0, 1);
    Job job = exampleProfileJob();
    cutcell::profileCutterSpec(job).other_branches.clear();
    job.cut.target = target;
    job.main_pipe.radius_mm = 40 + 160 * U(rng);
    job.main_pipe.wall_mm = 3 + 5 * U(rng);
    job.branch_pipe.radius_mm = (0.2 + 0.75 * U(rng)) * job.main_pipe.radius_mm;
    job.branch_pipe.wall_mm = std::min(0.3 * job.branch_pipe.radius_mm, 2 + 4 * U(rng));
    const double room = job.main_pipe.radius_mm - job.branch_pipe.radius_mm;
    job.eccentricity_mm = (2 * U(rng) - 1) * room;
    job.angle_deg = 25 + 65 * U(rng);
    if (U(rng) < 0.2) job.angle_deg = 90;
    // The branch must be long enough to hold its saddle (validateJob checks it): at a shallow
    // angle the cut end spans up to (R + 2 r cos a) / sin a along the branch.
    const double a = job.angle_deg * kPi / 180;
    const double saddle =
        (job.main_pipe.radius_mm + 2 * job.branch_pipe.radius_mm * std::cos(a)) / std::sin(a);
    job.branch_pipe.length_mm = std::max(job.branch_pipe.length_mm, saddle + 50);
    cutcell::profileCutterSpec(job).x_travel_mm =
        std::max(cutcell::profileCutterSpec(job).x_travel_mm, job.branch_pipe.length_mm + 100);
    return job;
}

} // namespace cutcell::test
