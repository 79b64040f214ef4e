#include "core/machines/profile_cutter/profile_lead.h"

#include "core/common/c_format.h"
#include "core/machine/pipe_joint_section.h"
#include "core/machines/profile_cutter/profile_kerf.h"
#include "core/process/lead_request.h"

#include <algorithm>
#include <cmath>

namespace cutcell {
namespace {

constexpr int kArcSegments = 16;
// A lead point closer than half the kerf minus this to the edge (or this far on the part's side)
// would mark the part: the edge polyline's chords miss the curve by less.
constexpr double kClearanceTolMm = 0.01;

// A point of the developed surface: x = X (mm), u = R_w A (mm).
struct D {
    double x, u;
};
D operator+(D a, D b) {
    return {a.x + b.x, a.u + b.u};
}
D operator*(double k, D a) {
    return {k * a.x, k * a.u};
}

D developed(const ProfileCut& c, const ProfilePoint& p) {
    return {p.x_mm, c.work_radius_mm * deg2rad(p.a_deg)};
}

ProfilePoint pointAt(const ProfileCut& c, const ProfilePoint& like, D d) {
    ProfilePoint p = like;
    p.x_mm = d.x;
    p.a_deg = rad2deg(d.u / c.work_radius_mm);
    p.edge_tangent = Vec3::Zero();
    return p;
}

D unit(D d) {
    const double n = std::hypot(d.x, d.u);
    return n > 0 ? D{d.x / n, d.u / n} : D{1, 0};
}

// The unit travel direction at grid point i (0 .. n, continuous A), from its neighbours.
D tangentAt(const ProfileCut& c, size_t i) {
    const size_t n = c.points.size();
    ProfilePoint prev = c.closedAt(i == 0 ? n - 1 : i - 1);
    if (i == 0) prev.a_deg -= c.a_per_turn_deg;
    const D a = developed(c, prev), b = developed(c, c.closedAt(i + 1));
    return unit({b.x - a.x, b.u - a.u});
}

// The normal toward the scrap: left of the travel (-u, x) when the scrap is on the left.
D scrapNormal(D t, bool left) {
    return left ? D{-t.u, t.x} : D{t.u, -t.x};
}

// The lead-in ending at the cut's start (not included), the pierce point first.
std::vector<D> leadInPoints(D p0, D t, D n, LeadKind kind, double L) {
    if (kind == LeadKind::Line) return {p0 + L * n};
    std::vector<D> out;
    const double r = 2 * L / kPi;
    for (int k = 0; k < kArcSegments; ++k) {
        const double th = -kPi / 2 * (1.0 - static_cast<double>(k) / kArcSegments);
        out.push_back(p0 + (r * (1 - std::cos(th))) * n + (r * std::sin(th)) * t);
    }
    return out;
}

// The lead-out leaving the cut at e (not included) toward the scrap.
std::vector<D> leadOutPoints(D e, D t, D n, LeadKind kind, double L) {
    if (kind == LeadKind::Line) return {e + L * n};
    std::vector<D> out;
    const double r = 2 * L / kPi;
    for (int k = 1; k <= kArcSegments; ++k) {
        const double th = kPi / 2 * static_cast<double>(k) / kArcSegments;
        out.push_back(e + (r * (1 - std::cos(th))) * n + (r * std::sin(th)) * t);
    }
    return out;
}

bool clear(const ProfileCut& cut, const ProfileCut& edge, const std::vector<D>& pts) {
    for (const D& d : pts) {
        const double a = rad2deg(d.u / cut.work_radius_mm);
        const double dist = profileDistanceToEdge(edge, d.x, a);
        if (dist < cut.kerf_mm / 2 - kClearanceTolMm) return false;
        if (!profileOnScrapSide(edge, d.x, a) && dist > kClearanceTolMm) return false;
    }
    return true;
}

// The longest length <= L whose lead is clear (bisection: a shorter lead stays nearer the
// start, on the scrap side).
template <class Make>
double longestClear(const ProfileCut& cut, const ProfileCut& edge, double L, Make make) {
    double lo = 0, hi = L;
    for (int k = 0; k < 40; ++k) {
        const double mid = (lo + hi) / 2;
        (clear(cut, edge, make(mid)) ? lo : hi) = mid;
    }
    return lo;
}

std::string tooLong(const ProfileCut& cut, const char* which, double L, double limit) {
    return messageC("process.%s.length_mm = %.6g mm is too long for the %s: the %s would reach "
                    "the part's edge [it must stay half the kerf, %.6g mm, off it on the scrap "
                    "side]; the longest that fits is %.3f mm",
                    which, L, cut.target == CutTarget::Main ? "hole" : "branch end",
                    std::string(which) == "lead_in" ? "lead-in" : "lead-out", cut.kerf_mm / 2,
                    limit);
}

} // namespace

bool profileOnScrapSide(const ProfileCut& edge, double x_mm, double a_deg) {
    // Crossings of the ray from the point toward +X with the closed edge: the hole's inside
    // (odd) or, for the branch end (A wraps), nothing beyond the point (even).
    const bool wraps = edge.a_per_turn_deg != 0;
    double a = a_deg;
    if (wraps) {
        const double a0 = edge.points.front().a_deg;
        a = a0 + std::fmod(std::fmod(a - a0, edge.a_per_turn_deg) + edge.a_per_turn_deg,
                           edge.a_per_turn_deg);
    }
    int crossings = 0;
    for (size_t i = 0; i < edge.points.size(); ++i) {
        const ProfilePoint p = edge.closedAt(i), q = edge.closedAt(i + 1);
        if ((p.a_deg <= a) == (q.a_deg <= a)) continue;
        const double t = (a - p.a_deg) / (q.a_deg - p.a_deg);
        if (p.x_mm + t * (q.x_mm - p.x_mm) > x_mm) ++crossings;
    }
    return wraps ? crossings % 2 == 0 : crossings % 2 == 1;
}

double profileDistanceToEdge(const ProfileCut& edge, double x_mm, double a_deg) {
    const double R = edge.work_radius_mm;
    double best = 1e300;
    for (size_t i = 0; i < edge.points.size(); ++i) {
        const ProfilePoint p = edge.closedAt(i), q = edge.closedAt(i + 1);
        double aa = a_deg;
        if (edge.a_per_turn_deg != 0)
            aa += edge.a_per_turn_deg * std::round((p.a_deg - a_deg) / edge.a_per_turn_deg);
        const double ux = q.x_mm - p.x_mm, uy = R * deg2rad(q.a_deg - p.a_deg);
        const double vx = x_mm - p.x_mm, vy = R * deg2rad(aa - p.a_deg);
        const double len2 = ux * ux + uy * uy;
        const double t = len2 > 0 ? std::clamp((vx * ux + vy * uy) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(vx - t * ux, vy - t * uy));
    }
    return best;
}

ProfileLeads computeProfileLeads(const Job& job, const ProfileCut& cut) {
    return computeProfileLeads(job, cut,
                               computeProfileEdge(job, static_cast<int>(cut.points.size())));
}

ProfileLeads computeProfileLeads(const Job& job, const ProfileCut& cut, const ProfileCut& edge) {
    ProfileLeads out;
    const LeadRequest r = requestLeads(job.process, cutPartWallMm(job));
    out.in = r.in;
    out.out = r.out;
    out.used = r.used;
    if (!out.used) return out;
    if (!r.problem.empty()) {
        out.problem = r.problem;
        out.problem_key = r.problem_key;
        return out;
    }
    const ProcessSettings& s = r.settings;
    // leadHeightProblem asks for the heights only with a lead; an overlap alone needs them too
    // here: the G-code runs it with the torch height (Z).
    const auto pierceHeight = s.effective.get(CutFigure::PierceHeightMm);
    const auto cutHeight = s.effective.get(CutFigure::CutHeightMm);
    if (!pierceHeight || !cutHeight) {
        const char* figure = !pierceHeight ? "pierce_height_mm" : "cut_height_mm";
        out.problem_key = std::string("process.override.") + figure;
        out.problem =
            messageC("process.lead_out.overlap_mm = %.6g mm: the profile cutter writes "
                     "the torch height (Z) with it, and the chart '%s' gives no %s; set "
                     "%s",
                     out.out.overlap_mm, s.chart_name.c_str(), figure, out.problem_key.c_str());
        return out;
    }
    out.pierce_height_mm = *pierceHeight;
    out.cut_height_mm = *cutHeight;
    out.pierce_delay_s =
        s.effective.get(CutFigure::PierceDelayS).value_or(profileCutterSpec(job).pierce_s);
    if (cut.points.size() < 3) {
        out.problem = "the cut has fewer than 3 points";
        return out;
    }
    const bool left = profileScrapOnLeft(cut);
    const size_t n = cut.points.size();

    if (out.in.used()) {
        const D p0 = developed(cut, cut.points[0]);
        const D t = tangentAt(cut, 0), nn = scrapNormal(t, left);
        auto make = [&](double L) { return leadInPoints(p0, t, nn, out.in.kind, L); };
        if (!clear(cut, edge, make(out.in.length_mm))) {
            out.problem = tooLong(cut, "lead_in", out.in.length_mm,
                                  longestClear(cut, edge, out.in.length_mm, make));
            out.problem_key = "process.lead_in.length_mm";
            return out;
        }
        for (const D& d : make(out.in.length_mm))
            out.lead_in.push_back(pointAt(cut, cut.points[0], d));
    }

    // The overlap: on along the cut past its closing point (index n), up to overlap_mm.
    std::vector<ProfilePoint> overlap;
    size_t i = n;
    D e = developed(cut, cut.closedAt(n));
    D t = tangentAt(cut, 0);
    double left_mm = out.out.overlap_mm;
    while (left_mm > 0) {
        const D a = developed(cut, cut.closedAt(i)), b = developed(cut, cut.closedAt(i + 1));
        const double seg = std::hypot(b.x - a.x, b.u - a.u);
        t = unit({b.x - a.x, b.u - a.u});
        if (seg >= left_mm) {
            e = a + (left_mm / seg) * D{b.x - a.x, b.u - a.u};
            overlap.push_back(pointAt(cut, cut.closedAt(i + 1), e));
            break;
        }
        left_mm -= seg;
        e = b;
        overlap.push_back(cut.closedAt(i + 1));
        ++i;
    }
    if (out.out.overlap_mm > 0 || out.out.used()) out.lead_out = overlap;
    if (out.out.used()) {
        const D nn = scrapNormal(t, left);
        auto make = [&](double L) { return leadOutPoints(e, t, nn, out.out.kind, L); };
        if (!clear(cut, edge, make(out.out.length_mm))) {
            out.problem = tooLong(cut, "lead_out", out.out.length_mm,
                                  longestClear(cut, edge, out.out.length_mm, make));
            out.problem_key = "process.lead_out.length_mm";
            out.lead_in.clear();
            out.lead_out.clear();
            return out;
        }
        for (const D& d : make(out.out.length_mm))
            out.lead_out.push_back(pointAt(cut, cut.points[0], d));
    }
    return out;
}

std::string leadTravelProblem(const Job& job, const ProfileLeads& leads) {
    const double travel = profileCutterSpec(job).x_travel_mm;
    for (const auto* pts : {&leads.lead_in, &leads.lead_out})
        for (const auto& p : *pts)
            if (p.x_mm < 0 || p.x_mm > travel)
                return messageC("the %s needs X = %.3f mm, outside the carriage travel 0 .. "
                                "machine.profile_cutter.x_travel_mm = %.3f mm",
                                pts == &leads.lead_in ? "lead-in" : "lead-out", p.x_mm, travel);
    return {};
}

} // namespace cutcell
