#include "core/machine/pipe_joint_section.h"
#include "core/process/process_spec.h"

#include "core/common/c_format.h"
#include "core/common/types.h"

#include <cmath>

namespace cutcell {
namespace {

PipeSpec readPipe(SectionReader r, double defaultLength) {
    PipeSpec p;
    p.radius_mm = r.number("radius_mm", "mm");
    p.wall_mm = r.number("wall_mm", "mm");
    p.length_mm = r.number("length_mm", "mm", defaultLength);
    r.finish();
    return p;
}

json::Value pipeJson(const PipeSpec& p) {
    return json::Object{
        {"radius_mm", p.radius_mm}, {"wall_mm", p.wall_mm}, {"length_mm", p.length_mm}};
}

void checkPipe(IssueChecker& c, const std::string& name, const PipeSpec& p) {
    c.positive(name + ".radius_mm", p.radius_mm, 1, 2000, "mm");
    c.positive(name + ".wall_mm", p.wall_mm, 0.1, 500, "mm");
    c.positive(name + ".length_mm", p.length_mm, 1, 20000, "mm");
    if (p.wall_mm > 0 && p.radius_mm > 0 && p.wall_mm >= p.radius_mm)
        c.add(name + ".wall_mm", messageC("%s.wall_mm = %.6g mm must be less than %s.radius_mm = "
                                          "%.6g mm",
                                          name.c_str(), p.wall_mm, name.c_str(), p.radius_mm));
}

} // namespace

void readPipeJoint(SectionReader& m, Job& job, const CutKeys& keys) {
    job.main_pipe = readPipe(m.child("main_pipe"), 1000);
    job.branch_pipe = readPipe(m.child("branch_pipe"), 300);
    job.angle_deg = m.number("angle_deg", "deg");
    job.eccentricity_mm = m.number("eccentricity_mm", "mm", 0);
    readProcess(m, job.process);
    SectionReader cut = m.child("cut");
    job.cut.target = cut.choice<CutTarget>(
        "target", {{"branch", CutTarget::Branch}, {"main", CutTarget::Main}}, CutTarget::Main);
    if (keys.bevel) job.cut.bevel_deg = cut.number("bevel_deg", "deg", 0);
    // With a process section the cut chart gives the speed: a second speed in the file would
    // contradict it (the override is where an operator sets another).
    if (!job.process.used)
        job.cut.speed_mm_s = cut.number("speed_mm_s", "mm/s");
    else if (cut.has("speed_mm_s"))
        throw JobError(cut.key("speed_mm_s") +
                       " is given by the cut chart when the job has a process section; set "
                       "process.override.cut_speed_mm_min to cut at another speed");
    job.cut.ramp_s = cut.number("ramp_s", "s", job.cut.ramp_s);
    if (keys.direction_deviation)
        job.cut.max_direction_deviation_deg =
            cut.number("max_direction_deviation_deg", "deg", job.cut.max_direction_deviation_deg);
    job.cut.knot_spacing_mm = cut.number("knot_spacing_mm", "mm", job.cut.knot_spacing_mm);
    if (keys.static_chuck)
        job.cut.static_chuck_deg = cut.number("static_chuck_deg", "deg", job.cut.static_chuck_deg);
    if (keys.start_phi) {
        job.cut.start_phi_auto = !cut.has("start_phi_deg");
        job.cut.start_phi_deg = cut.number("start_phi_deg", "deg", 0);
    }
    cut.finish();
    syncProcessSpeed(job);
}

double cutPartWallMm(const Job& job) {
    return job.cut.target == CutTarget::Main ? job.main_pipe.wall_mm : job.branch_pipe.wall_mm;
}

void syncProcessSpeed(Job& job) {
    if (!job.process.used) return;
    const ProcessSettings s = resolveProcess(job.process, cutPartWallMm(job));
    job.cut.speed_mm_s = s.ok() ? s.cutSpeedMmS() : 0.0;
}

void writePipeJoint(const Job& job, json::Object& s, const CutKeys& keys) {
    s.emplace_back("main_pipe", pipeJson(job.main_pipe));
    s.emplace_back("branch_pipe", pipeJson(job.branch_pipe));
    s.emplace_back("angle_deg", job.angle_deg);
    s.emplace_back("eccentricity_mm", job.eccentricity_mm);
    writeProcess(job.process, s);
    json::Object cut{{"target", toString(job.cut.target)}};
    if (keys.bevel) cut.emplace_back("bevel_deg", job.cut.bevel_deg);
    if (!job.process.used) cut.emplace_back("speed_mm_s", job.cut.speed_mm_s);
    cut.emplace_back("ramp_s", job.cut.ramp_s);
    if (keys.direction_deviation)
        cut.emplace_back("max_direction_deviation_deg", job.cut.max_direction_deviation_deg);
    cut.emplace_back("knot_spacing_mm", job.cut.knot_spacing_mm);
    if (keys.static_chuck) cut.emplace_back("static_chuck_deg", job.cut.static_chuck_deg);
    if (keys.start_phi && !job.cut.start_phi_auto)
        cut.emplace_back("start_phi_deg", job.cut.start_phi_deg);
    s.emplace_back("cut", cut);
}

void checkPipeJoint(IssueChecker& c, const Job& job, const CutKeys& keys) {
    checkPipe(c, "main_pipe", job.main_pipe);
    checkPipe(c, "branch_pipe", job.branch_pipe);
    // Below 0.1 deg the branch runs along the main pipe: no closed cut of sensible size.
    if (!(job.angle_deg >= 0.1 && job.angle_deg <= 90))
        c.add("angle_deg", messageC("angle_deg = %.6g deg is outside [0.1, 90] deg (angle "
                                    "between the pipe axes)",
                                    job.angle_deg));
    c.range("eccentricity_mm", job.eccentricity_mm, -2000, 2000, "mm");
    const double R = job.main_pipe.radius_mm, r = job.branch_pipe.radius_mm;
    const double fit = std::fabs(job.eccentricity_mm) + r;
    if (R > 0 && r > 0 && fit > R)
        c.add("branch_pipe.radius_mm",
              messageC("branch_pipe.radius_mm = %.6g mm does not fit: |eccentricity_mm| + branch "
                       "radius = %.6g mm must be <= main_pipe.radius_mm = %.6g mm",
                       r, fit, R));

    if (keys.bevel) c.range("cut.bevel_deg", job.cut.bevel_deg, -60, 60, "deg");
    // 0.1 mm/s: slower than any torch cuts; with 500 mm/s the upper bound of the machines. With
    // a process section the speed is the chart's (or its override): its issues are process.*.
    checkProcess(c, job.process, cutPartWallMm(job));
    if (!job.process.used)
        c.positive("cut.speed_mm_s", job.cut.speed_mm_s, 0.1, 500, "mm/s");
    else if (!c.has("process.thickness_mm") && !c.has("process.material") &&
             !c.has("process.consumable") && !c.has("process.override.cut_speed_mm_min"))
        c.positive("process.override.cut_speed_mm_min", job.cut.speed_mm_s * 60, 6, 30000,
                   "mm/min");
    c.range("cut.ramp_s", job.cut.ramp_s, 0.01, 10, "s");
    if (keys.direction_deviation)
        c.range("cut.max_direction_deviation_deg", job.cut.max_direction_deviation_deg, 0, 90,
                "deg");
    c.range("cut.knot_spacing_mm", job.cut.knot_spacing_mm, 0.05, 20, "mm");
    if (keys.start_phi && !job.cut.start_phi_auto)
        c.range("cut.start_phi_deg", job.cut.start_phi_deg, -360, 360, "deg");
    if (keys.static_chuck)
        c.range("cut.static_chuck_deg", job.cut.static_chuck_deg, -180, 180, "deg");

    // The plan's size: estimate the cut's length from above (the intersection curve of a
    // branch of radius r at angle a is at most 2 pi r / sin a long, plus the eccentric part).
    const double a = deg2rad(job.angle_deg);
    if (R > 0 && r > 0 && fit <= R && job.angle_deg >= 0.1 && job.angle_deg <= 90 &&
        job.cut.speed_mm_s > 0) {
        const double lengthBound = 2 * kPi * r / std::sin(a) + 2 * kPi * R;
        const double time = lengthBound / job.cut.speed_mm_s;
        const double typical = 2 * kPi * r / job.cut.speed_mm_s; // a right-angle branch
        if (typical > kMaxCutTime_s)
            c.add("cut.speed_mm_s",
                  messageC("cut.speed_mm_s = %.6g mm/s: the cut around the branch (about %.6g "
                           "mm) would take %.6g s, longer than the limit of %.6g s (one hour)",
                           job.cut.speed_mm_s, 2 * kPi * r, typical, kMaxCutTime_s));
        else if (job.sim.period_s > 0 && time / job.sim.period_s > kMaxPlanSamples)
            c.add("cut.speed_mm_s",
                  messageC("cut.speed_mm_s = %.6g mm/s: the cut (up to %.6g mm, %.6g s) would "
                           "need %.6g samples at sim.period_s = %.6g s; the limit is %.6g",
                           job.cut.speed_mm_s, lengthBound, time, time / job.sim.period_s,
                           job.sim.period_s, kMaxPlanSamples));
    }

    // The pipes must be long enough to hold the cut. A branch point at parameter phi lies at
    // z = -r cos(phi) / sin a + y cot a along the main pipe and t = (y - r cos(phi) cos a) / sin a
    // along the branch, with y on the main pipe between ymin = sqrt(R^2 - (|e| + r)^2) and R.
    if (R > 0 && r > 0 && fit <= R && job.angle_deg >= 0.1 && job.angle_deg <= 90) {
        const double ymin = std::sqrt(std::max(0.0, R * R - fit * fit));
        const double along = 2 * r / std::sin(a) + (R - ymin) / std::tan(a);
        if (job.main_pipe.length_mm > 0 && job.main_pipe.length_mm < along)
            c.add("main_pipe.length_mm",
                  messageC("main_pipe.length_mm = %.6g mm is shorter than the cut along it (%.6g "
                           "mm for a branch of radius %.6g mm at %.6g deg): the pipe must contain "
                           "the cut",
                           job.main_pipe.length_mm, along, r, job.angle_deg));
        const double saddle = (R - ymin + 2 * r * std::cos(a)) / std::sin(a);
        if (job.branch_pipe.length_mm > 0 && job.branch_pipe.length_mm < saddle)
            c.add("branch_pipe.length_mm",
                  messageC("branch_pipe.length_mm = %.6g mm is shorter than the saddle of its cut "
                           "end (%.6g mm): the pipe must contain the cut",
                           job.branch_pipe.length_mm, saddle));
    }
}

} // namespace cutcell
