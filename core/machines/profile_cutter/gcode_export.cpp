#include "core/machines/profile_cutter/gcode_export.h"
#include "core/common/c_format.h"

#include <cmath>
#include <cstdio>

namespace cutcell {
namespace {

// A G-code comment may not hold parentheses or line breaks.
std::string commentText(const std::string& s) {
    std::string out;
    for (char c : s)
        out += c == '(' ? '[' : c == ')' ? ']' : (c >= 32 && c < 127) ? c : ' ';
    return out;
}

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
    char buf[256];
    snprintfC(buf, sizeof buf, f, a, b, c, d);
    return buf;
}

// The value as written with 4 decimals, so F matches the coordinates LinuxCNC reads.
double written(double v) {
    return std::round(v * 1e4) / 1e4;
}

} // namespace

std::string profileGcode(const Job& job, const ProfileCut& cut, GcodeStats* stats) {
    return profileGcode(job, cut, ProfileLeads{}, stats);
}

std::string profileGcode(const Job& job, const ProfileCut& cut, const ProfileLeads& leads,
                         GcodeStats* stats) {
    std::string g;
    auto line = [&g](const std::string& s) { g += s + "\n"; };
    auto comment = [&line](const std::string& s) { line("(" + commentText(s) + ")"); };
    const double v = job.cut.speed_mm_s;

    comment(
        "CutCell profile cutter program, machine profile_cutter_2axis, X linear mm, A rotary deg");
    comment("job: " + job.name);
    comment(job.cut.target == CutTarget::Branch ? "cut: branch pipe end [saddle]; X = distance "
                                                  "from the branch's fixed end, A = branch turn"
                                                : "cut: hole in the main pipe; X = distance from "
                                                  "the main pipe's fixed end, A = main pipe turn");
    comment(fmt("main pipe: radius %.3f mm, wall %.3f mm, length %.1f mm", job.main_pipe.radius_mm,
                job.main_pipe.wall_mm, job.main_pipe.length_mm));
    comment(fmt("branch pipe: radius %.3f mm, wall %.3f mm, length %.1f mm",
                job.branch_pipe.radius_mm, job.branch_pipe.wall_mm, job.branch_pipe.length_mm));
    comment(fmt("angle %.3f deg, eccentricity %.3f mm", job.angle_deg, job.eccentricity_mm));
    if (job.cut.target == CutTarget::Branch)
        for (size_t k = 0; k < profileCutterSpec(job).other_branches.size(); ++k) {
            const OtherBranch& o = profileCutterSpec(job).other_branches[k];
            comment("other branch " + std::to_string(k + 1) +
                    fmt(": radius %.3f mm, angle %.3f deg, eccentricity %.3f mm, position %.3f mm",
                        o.radius_mm, o.angle_deg, o.eccentricity_mm, o.position_mm) +
                    fmt(", phase %.3f deg", o.phase_deg));
        }
    comment(fmt("cutting speed %.3f mm/s on the pipe surface, work radius %.3f mm, %.0f steps/rev, "
                "pierce %.2f s",
                v, cut.work_radius_mm, static_cast<double>(profileCutterSpec(job).steps_per_rev_a),
                leads.used ? leads.pierce_delay_s : profileCutterSpec(job).pierce_s));
    // The compensation is in the coordinates, not in the controller (G40 stays): the program
    // runs the same on a control without cutter-radius compensation on a rotary axis.
    if (cut.kerf_mm > 0)
        comment(fmt("kerf compensation: X/A below are the torch centre's, %.3f mm [half the kerf "
                    "%.3f mm] off the part edge toward the scrap side; G40, none in the control",
                    cut.kerf_mm / 2, cut.kerf_mm));
    else
        comment("no kerf compensation: X/A below are the part edge");
    if (leads.used) {
        comment(fmt("torch height Z: mm over the pipe surface, a simulated axis [no Z drive]; "
                    "pierce at %.3f mm, cut at %.3f mm, pierce delay %.2f s",
                    leads.pierce_height_mm, leads.cut_height_mm, leads.pierce_delay_s));
        comment(std::string("lead-in: ") + toString(leads.in.kind) +
                (leads.in.used() ? fmt(" %.3f mm", leads.in.length_mm) : "") +
                "; lead-out: " + toString(leads.out.kind) +
                (leads.out.used() ? fmt(" %.3f mm", leads.out.length_mm) : "") +
                fmt(", overlap %.3f mm; on the scrap side", leads.out.overlap_mm));
    }
    line("G21 G90 G17 G40 G94");
    const ProfilePoint first = leads.lead_in.empty() ? cut.points.front() : leads.lead_in.front();
    const double pierce = leads.used ? leads.pierce_delay_s : profileCutterSpec(job).pierce_s;
    if (!leads.used) {
        line(fmt("G0 X%.4f A%.4f", written(first.x_mm), written(first.a_deg)));
    } else {
        // The torch to its pierce height before it travels (not at whatever height it had).
        line(fmt("G0 Z%.4f (pierce height)", written(leads.pierce_height_mm)));
        comment(leads.lead_in.empty() ? "rapid to the cut's start"
                                      : "rapid to the pierce point, on the scrap side");
        line(fmt("G0 X%.4f A%.4f", written(first.x_mm), written(first.a_deg)));
    }
    line("M3 S1 (torch on)");
    if (pierce > 0) line(fmt("G4 P%.3f (pierce)", pierce));
    if (leads.used)
        line(
            fmt("G1 Z%.4f F%.4f (down to the cut height)", written(leads.cut_height_mm), 60.0 * v));
    line("G93 (inverse time feed: F = 1 / minutes per move, constant surface speed)");

    GcodeStats st;
    double px = written(first.x_mm), pa = written(first.a_deg);
    auto feedTo = [&](const ProfilePoint& p) {
        const double x = written(p.x_mm), a = written(p.a_deg);
        const double ds = std::hypot(x - px, cut.work_radius_mm * deg2rad(a - pa));
        if (ds <= 0) return;
        const double f = 60.0 * v / ds;
        line(fmt("G1 X%.4f A%.4f F%.4f", x, a, f));
        ++st.moves;
        st.length_mm += ds;
        st.time_s += 60.0 / f;
        px = x;
        pa = a;
    };
    if (!leads.lead_in.empty()) {
        comment("lead-in");
        for (size_t i = 1; i < leads.lead_in.size(); ++i)
            feedTo(leads.lead_in[i]);
        feedTo(cut.points.front());
    }
    if (leads.used) comment("cut");
    for (size_t i = 1; i <= cut.points.size(); ++i)
        feedTo(cut.closedAt(i));
    if (!leads.lead_out.empty()) {
        comment("lead-out");
        for (const ProfilePoint& p : leads.lead_out)
            feedTo(p);
    }
    line("G94");
    line("M5 (torch off)");
    if (leads.used) line(fmt("G0 Z%.4f (torch up)", written(leads.pierce_height_mm)));
    comment(fmt("%.0f moves, developed length %.3f mm, cutting time %.2f s",
                static_cast<double>(st.moves), st.length_mm, st.time_s));
    line("M2");
    if (stats) *stats = st;
    return g;
}

} // namespace cutcell
