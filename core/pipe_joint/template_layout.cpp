#include "core/pipe_joint/template_layout.h"
#include "core/common/c_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cutcell {
namespace {

constexpr double kMargin = 12;    // mm, printers need ~5 mm
constexpr double kLineStep = 5.5; // mm between text lines
constexpr double kTextSize = 3.5; // mm
constexpr double kGlueTab = 15;   // mm, overlap of the wrapped sheet

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
    char buf[256];
    snprintfC(buf, sizeof buf, f, a, b, c, d);
    return buf;
}

// Job text is printed into SVG and PDF: keep printable ASCII only.
std::string ascii(const std::string& s) {
    std::string out;
    for (char ch : s)
        out += (ch >= 32 && ch < 127) ? ch : '?';
    return out;
}

std::vector<std::string> captions(const Job& job, const JointExtras& extras, const ProfileCut& cut,
                                  double xRef) {
    std::vector<std::string> t;
    t.push_back("CutCell cutting template: " + ascii(job.name));
    t.push_back(
        job.cut.target == CutTarget::Branch
            ? "Branch pipe end (saddle): wrap round the BRANCH pipe, cut along the curve; keep the "
              "reference-line side"
            : "Hole in the main pipe: wrap round the MAIN pipe, cut out the closed curve (inside "
              "is "
              "scrap)");
    t.push_back(fmt("main pipe OD %.2f mm, wall %.2f mm; branch pipe OD %.2f mm, wall %.2f mm",
                    2 * job.main_pipe.radius_mm, job.main_pipe.wall_mm,
                    2 * job.branch_pipe.radius_mm, job.branch_pipe.wall_mm));
    t.push_back(fmt("angle between axes %.2f deg, eccentricity %.2f mm", job.angle_deg,
                    job.eccentricity_mm));
    for (size_t k = 0; k < extras.other_branches.size() && job.cut.target == CutTarget::Branch;
         ++k) {
        const OtherBranch& o = extras.other_branches[k];
        t.push_back("also fits other branch " + std::to_string(k + 1) +
                    fmt(": OD %.2f mm, angle %.2f deg, eccentricity %.2f mm, position %.2f mm",
                        2 * o.radius_mm, o.angle_deg, o.eccentricity_mm, o.position_mm) +
                    fmt(", phase %.2f deg", o.phase_deg));
    }
    t.push_back(
        fmt("width = circumference 2 pi R = %.2f mm (R = %.2f mm); reference line at X = %.1f mm "
            "from the pipe's fixed end",
            2 * kPi * cut.work_radius_mm, cut.work_radius_mm, xRef));
    t.push_back("Print at 100 % (1:1, no fit to page); check the scale bar before cutting.");
    return t;
}

// Where the 0 deg line lies on the pipe: A = 0 is the generator under the torch at chuck zero
// (profile_cutter.h: branch A = beta, phi = beta + 90 deg, the main frame's +x side; hole
// A = alpha from +y, the branch side).
std::vector<std::string> zeroAndWrap(const Job& job, const TemplateDrawing& d, double odMm) {
    std::vector<std::string> t;
    if (job.cut.target == CutTarget::Branch) {
        t.push_back(
            "0 deg line (A = 0, under the torch at chuck zero): the branch generator square "
            "to the plane of both");
        t.push_back("pipe axes, on the side a positive eccentricity moves the branch to.");
        t.push_back(job.angle_deg < 90 - 1e-9
                        ? "90 deg: the acute-angle side of the joint, 270 deg: the obtuse side."
                        : "90 deg: toward the main pipe's +z end (its far end), 270 deg: toward "
                          "its fixed end.");
        t.push_back("Wrap round the branch, printed side out, top edge toward the end being cut "
                    "(away from the chuck):");
    } else {
        t.push_back("0 deg line (A = 0, under the torch at chuck zero): the main pipe generator in "
                    "line with the branch");
        t.push_back("axis (the crown on the branch side); 90 deg: the side a positive eccentricity "
                    "moves the branch to.");
        t.push_back("Wrap round the main pipe, printed side out, top edge toward its fixed end "
                    "(X = 0, at the chuck):");
    }
    // The wrap edges are 0 / 360 deg on the branch end and -180 / 180 deg on the hole.
    const double left = d.a_low_deg, right = d.a_low_deg + 360;
    t.push_back(fmt("seen from that end, A grows counter-clockwise (arrow). The %.0f deg edge goes "
                    "over the glue tab.",
                    left));
    t.push_back(fmt("glue tab %.0f mm wide right of the last edge; pipe OD %.2f mm, circumference "
                    "%.2f mm",
                    d.glue_tab_mm, odMm, d.circumference_mm) +
                fmt(" (%.0f .. %.0f deg).", left, right));
    return t;
}

} // namespace

TemplateDrawing buildTemplate(const Job& job, const JointExtras& extras, int samples) {
    const ProfileCut cut = computeProfileCut(job, extras, samples);
    TemplateDrawing d;
    d.circumference_mm = 2 * kPi * cut.work_radius_mm;
    d.a_low_deg = cut.target == CutTarget::Branch ? 0.0 : -180.0;
    double xMin = 1e300, xMax = -1e300;
    for (const auto& p : cut.points) {
        xMin = std::min(xMin, p.x_mm);
        xMax = std::max(xMax, p.x_mm);
    }
    // The reference line lies 15+ mm off the cut toward the bottom of the sheet (see y_per_x).
    const bool hole = cut.target == CutTarget::Main;
    const double xRef = hole ? 5 * std::ceil((xMax + 15) / 5) : 5 * std::floor((xMin - 15) / 5);
    const auto caption = captions(job, extras, cut, xRef);
    const double textTop = kMargin + kTextSize;
    for (size_t i = 0; i < caption.size(); ++i)
        d.texts.push_back({{kMargin, textTop + kLineStep * static_cast<double>(i)},
                           kTextSize,
                           caption[i],
                           false});

    d.origin_u_mm = kMargin;
    d.top_mm = textTop + kLineStep * static_cast<double>(caption.size()) + 8;
    d.y_per_x = hole ? 1 : -1;
    d.x_top_mm = hole ? xMin : xMax;
    const double bottom = d.top_mm + d.y_per_x * (xRef - d.x_top_mm);
    auto page = [&](double aDeg, double x) {
        return Eigen::Vector2d(d.origin_u_mm + cut.work_radius_mm * deg2rad(aDeg - d.a_low_deg),
                               d.top_mm + d.y_per_x * (x - d.x_top_mm));
    };

    TemplateDrawing::Polyline curve{"cut", {}, 0.35, cut.target == CutTarget::Main};
    const size_t last = cut.target == CutTarget::Branch ? cut.points.size() : cut.points.size() - 1;
    for (size_t i = 0; i <= last; ++i) {
        const ProfilePoint p = cut.closedAt(i);
        curve.points.push_back(page(p.a_deg, p.x_mm));
    }
    d.lines.push_back(curve);

    // Wrap edges and quadrant marks, labelled with A.
    for (int k = 0; k <= 4; ++k) {
        const double a = d.a_low_deg + 90.0 * k;
        const Eigen::Vector2d top = page(a, d.x_top_mm), foot = page(a, xRef);
        const bool edge = k == 0 || k == 4;
        d.lines.push_back(
            {edge ? "edge" : "quadrant", {{top.x(), top.y() - 4}, foot}, edge ? 0.3 : 0.15, false});
        d.texts.push_back({{top.x(), top.y() - 5}, kTextSize, fmt("%.0f deg", a), true});
    }
    d.lines.push_back(
        {"reference", {page(d.a_low_deg, xRef), page(d.a_low_deg + 360, xRef)}, 0.3, false});
    d.texts.push_back(
        {{d.origin_u_mm + 2, bottom + 4.5},
         kTextSize,
         fmt("reference line X = %.1f mm (align with a line scribed round the pipe)", xRef),
         false});

    // Scale bar: 100 mm (50 mm on small pipes), ticks every 10 mm.
    d.scale_bar_mm = d.circumference_mm >= 110 ? 100 : 50;
    const double sy = bottom + 16, sx = d.origin_u_mm;
    d.lines.push_back({"scale", {{sx, sy}, {sx + d.scale_bar_mm, sy}}, 0.4, false});
    for (int k = 0; k * 10 <= static_cast<int>(d.scale_bar_mm); ++k) {
        const double x = sx + 10.0 * k, h = (k % 5 == 0) ? 4 : 2;
        d.lines.push_back({"scale", {{x, sy - h}, {x, sy}}, 0.25, false});
    }
    d.texts.push_back({{sx + d.scale_bar_mm + 3, sy},
                       kTextSize,
                       fmt("%.0f mm at 1:1 (ticks every 10 mm)", d.scale_bar_mm),
                       false});

    // Glue tab right of the last wrap edge (it goes under the 0 deg edge when wrapped).
    d.glue_tab_mm = kGlueTab;
    const double tabX = d.origin_u_mm + d.circumference_mm, tabTop = d.top_mm;
    d.lines.push_back({"tab",
                       {{tabX, tabTop},
                        {tabX + kGlueTab, tabTop + 4},
                        {tabX + kGlueTab, bottom - 4},
                        {tabX, bottom}},
                       0.2,
                       false});
    const double tabMid = (tabTop + bottom) / 2;
    for (int k = 0; k < 3; ++k)
        d.texts.push_back({{tabX + kGlueTab / 2, tabMid + 4.0 * (k - 1)},
                           3.0,
                           k == 0   ? "glue"
                           : k == 1 ? "tab"
                                    : fmt("%.0f mm", kGlueTab),
                           true});

    // The 0 deg line: a triangle under the reference line pointing at it.
    d.zero_u_mm = page(0, xRef).x();
    const double zx = d.zero_u_mm;
    d.lines.push_back(
        {"zero", {{zx, bottom + 0.5}, {zx - 1.8, bottom + 4}, {zx + 1.8, bottom + 4}}, 0.4, true});

    // Wrap direction: an arrow along +A from the 0 deg line, then the sentences.
    const double wy = sy + 11;
    d.lines.push_back({"wrap", {{zx, wy}, {zx + 60, wy}}, 0.4, false});
    d.lines.push_back({"wrap", {{zx + 55, wy - 2}, {zx + 60, wy}, {zx + 55, wy + 2}}, 0.4, false});
    d.texts.push_back({{zx + 63, wy + 1.2}, kTextSize, "wrap direction: A grows this way", false});
    const auto notes = zeroAndWrap(job, d, 2 * cut.work_radius_mm);
    for (size_t i = 0; i < notes.size(); ++i)
        d.texts.push_back(
            {{kMargin, wy + 9 + kLineStep * static_cast<double>(i)}, kTextSize, notes[i], false});

    d.width_mm = std::max(d.circumference_mm + kGlueTab + 2 * kMargin, 215.0);
    d.height_mm = wy + 9 + kLineStep * static_cast<double>(notes.size() - 1) + 2 + kMargin;
    return d;
}

} // namespace cutcell
