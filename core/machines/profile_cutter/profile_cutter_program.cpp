#include "core/machines/profile_cutter/profile_cutter_program.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"

#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/trajectory/speed_profile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace cutcell {

Vec3 ProfileCutterTipModel::tip(const JointVector& q) const {
    return {r_ * std::sin(q[0]), r_ * std::cos(q[0]), q[1]};
}

DevelopedPath::DevelopedPath(const ProfileCut& cut) {
    const size_t n = cut.points.size();
    s_.reserve(n + 1);
    a_.reserve(n + 1);
    x_.reserve(n + 1);
    double s = 0;
    for (size_t i = 0; i <= n; ++i) {
        const ProfilePoint p = cut.closedAt(i);
        if (i > 0)
            s += std::hypot(p.x_mm - x_.back(), cut.work_radius_mm * deg2rad(p.a_deg - a_.back()));
        s_.push_back(s);
        a_.push_back(p.a_deg);
        x_.push_back(p.x_mm);
    }
}

void DevelopedPath::at(double s, double* aDeg, double* xMm) const {
    s = std::clamp(s, 0.0, length());
    const size_t i = std::min<size_t>(
        static_cast<size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin()), s_.size() - 1);
    const size_t lo = i == 0 ? 0 : i - 1;
    const double span = s_[i] - s_[lo];
    const double u = span > 0 ? (s - s_[lo]) / span : 0;
    *aDeg = a_[lo] + u * (a_[i] - a_[lo]);
    *xMm = x_[lo] + u * (x_[i] - x_[lo]);
}

namespace {

// The program's common part (axes, limits, tip model, names).
std::shared_ptr<MotionProgram> newProgram(const Job& job, const ProfileCut& cut,
                                          const std::string& jobText) {
    auto p = std::make_shared<MotionProgram>();
    p->machine = kProfileCutterId;
    p->method = "rotating_pipe";
    p->axis_count = 2;
    p->axis_names = {"A (pipe turn)", "X (torch carriage)", "", "", "", ""};
    p->axis_linear = {false, true, false, false, false, false};
    p->reference = JointVector::Zero();
    p->min_position[1] = 0;
    p->max_position[1] = profileCutterSpec(job).x_travel_mm;
    p->tip_model = std::make_shared<ProfileCutterTipModel>(cut.work_radius_mm);
    p->name = job.name;
    p->source_text = jobText.empty() ? json::write(jobToJson(job)) : jobText;
    return p;
}

// The profile's time at which it has covered s (bisection: distance() is monotone).
double timeAt(const SpeedProfile& profile, double s) {
    double lo = 0, hi = profile.duration();
    if (s <= 0) return 0;
    for (int k = 0; k < 100 && hi - lo > 1e-13 * profile.duration(); ++k) {
        const double mid = (lo + hi) / 2;
        (profile.distance(mid) < s ? lo : hi) = mid;
    }
    return hi;
}

// The cut alone (no leads): the cut's speed profile sampled at equal time steps.
std::shared_ptr<const MotionProgram> cutOnlyProgram(const Job& job, const ProfileCut& cut,
                                                    const DevelopedPath& path,
                                                    const std::string& jobText,
                                                    ProfileProgramLayout* layout) {
    const SpeedProfile profile(path.length(), job.cut.speed_mm_s, job.cut.ramp_s);
    const double cutTime = profile.duration();
    const int intervals =
        std::max(16, static_cast<int>(std::ceil(path.length() / job.cut.knot_spacing_mm)));
    const double dt = cutTime / intervals;
    std::vector<JointVector> knots;
    knots.reserve(static_cast<size_t>(intervals) + 1);
    for (int k = 0; k <= intervals; ++k) {
        double a = 0, x = 0;
        path.at(profile.distance(dt * k), &a, &x);
        JointVector q = JointVector::Zero();
        q[0] = deg2rad(a);
        q[1] = x;
        knots.push_back(q);
    }

    auto p = newProgram(job, cut, jobText);
    p->reference[1] = knots.front()[1]; // A at 0, the torch over the start's X
    p->spline = JointSpline(std::move(knots), dt);
    p->cut_time_s = cutTime;
    p->length_mm = path.length();
    p->point_count = static_cast<size_t>(intervals) + 1;
    const double ramp = cutTime - path.length() / job.cut.speed_mm_s;
    p->cruise_from_s = ramp;
    p->cruise_to_s = cutTime - ramp;
    p->pierce_s = profileCutterSpec(job).pierce_s; // as the G-code's G4 after M3
    if (layout) {
        *layout = ProfileProgramLayout{};
        layout->cut_last_knot = static_cast<size_t>(intervals);
    }
    return p;
}

// Lead-in, cut and lead-out under one speed profile; every lead point a knot (see the header).
std::shared_ptr<const MotionProgram>
leadProgram(const Job& job, const ProfileCut& cut, const DevelopedPath& path,
            const ProfileLeads& leads, const std::string& jobText, ProfileProgramLayout* layout) {
    struct Anchor {
        double s, a, x; // developed distance from the pierce point; A (deg), X (mm)
    };
    const double R = cut.work_radius_mm;
    std::vector<Anchor> anchors;
    double s = 0;
    auto add = [&](double a, double x) {
        if (!anchors.empty())
            s += std::hypot(x - anchors.back().x, R * deg2rad(a - anchors.back().a));
        anchors.push_back({s, a, x});
    };
    for (const ProfilePoint& pt : leads.lead_in)
        add(pt.a_deg, pt.x_mm);
    const size_t cutFirst = anchors.size();
    double a = 0, x = 0;
    path.at(0, &a, &x);
    add(a, x);
    const double cutStart = s;
    path.at(path.length(), &a, &x);
    s += path.length();
    anchors.push_back({s, a, x});
    const size_t cutLast = anchors.size() - 1;
    for (const ProfilePoint& pt : leads.lead_out)
        add(pt.a_deg, pt.x_mm);
    const double total = s;

    const double v = job.cut.speed_mm_s;
    const SpeedProfile profile(total, v, job.cut.ramp_s);
    const double T = profile.duration();
    std::vector<double> t(anchors.size());
    for (size_t j = 0; j < anchors.size(); ++j)
        t[j] = j + 1 == anchors.size() ? T : timeAt(profile, anchors[j].s);

    // The step: the cut's (about knot_spacing_mm apart), finer where a lead's stretches are
    // short (a quarter of the shortest one's time, so that rounding its steps up slows the
    // torch there by a fifth at most), but no finer than a sixteenth of the cut's.
    const int n0 = std::max(16, static_cast<int>(std::ceil(total / job.cut.knot_spacing_mm)));
    const double dt0 = T / n0;
    double shortest = dt0 * 4;
    for (size_t j = 0; j + 1 < anchors.size(); ++j)
        if (j != cutFirst && anchors[j + 1].s - anchors[j].s > 1e-6)
            shortest = std::min(shortest, t[j + 1] - t[j]);
    const double dt = std::clamp(shortest / 4, dt0 / 16, dt0);

    std::vector<size_t> at(anchors.size(), 0); // the knot of every anchor
    std::vector<JointVector> knots;
    auto push = [&knots](double aDeg, double xMm) {
        JointVector q = JointVector::Zero();
        q[0] = deg2rad(aDeg);
        q[1] = xMm;
        knots.push_back(q);
    };
    for (size_t j = 0; j + 1 < anchors.size(); ++j) {
        const Anchor &p0 = anchors[j], &p1 = anchors[j + 1];
        // Whole steps, never fewer than the profile's time needs (never faster than it).
        const int m = std::max(1, static_cast<int>(std::ceil((t[j + 1] - t[j]) / dt - 1e-6)));
        at[j] = knots.size();
        push(p0.a, p0.x);
        for (int i = 1; i < m; ++i) {
            const double tau = t[j] + (t[j + 1] - t[j]) * i / m;
            const double si = std::clamp(profile.distance(tau), p0.s, p1.s);
            if (j == cutFirst) {
                path.at(si - cutStart, &a, &x);
            } else {
                const double u = p1.s > p0.s ? (si - p0.s) / (p1.s - p0.s) : 0.0;
                a = p0.a + u * (p1.a - p0.a);
                x = p0.x + u * (p1.x - p0.x);
            }
            push(a, x);
        }
    }
    at.back() = knots.size();
    push(anchors.back().a, anchors.back().x);

    // The profile's time tau on the program's clock (linear within a stretch between anchors).
    auto clock = [&](double tau) {
        for (size_t j = 0; j + 1 < anchors.size(); ++j)
            if (tau <= t[j + 1] || j + 2 == anchors.size()) {
                const double span = t[j + 1] - t[j];
                const double u = span > 0 ? std::clamp((tau - t[j]) / span, 0.0, 1.0) : 0.0;
                return dt *
                       (static_cast<double>(at[j]) + u * static_cast<double>(at[j + 1] - at[j]));
            }
        return 0.0;
    };

    const size_t points = knots.size();
    auto p = newProgram(job, cut, jobText);
    p->reference[1] = knots.front()[1]; // A at 0, the torch over the pierce point's X
    p->spline = JointSpline(std::move(knots), dt);
    p->cut_time_s = dt * static_cast<double>(points - 1);
    p->length_mm = total; // the torch's whole lit path: lead-in, cut, lead-out
    p->point_count = points;
    // Constant cutting speed on the cut only (the leads and the ramps excluded).
    const double ramp = T - total / v;
    p->cruise_from_s = std::max(clock(ramp), dt * static_cast<double>(at[cutFirst]));
    p->cruise_to_s = std::min(clock(T - ramp), dt * static_cast<double>(at[cutLast]));
    p->pierce_s = leads.pierce_delay_s; // lit at the pierce point: the G-code's G4 after M3
    if (layout) {
        *layout = ProfileProgramLayout{};
        layout->lead_in_knots.assign(at.begin(), at.begin() + static_cast<long>(cutFirst));
        layout->cut_first_knot = at[cutFirst];
        layout->cut_last_knot = at[cutLast];
        layout->lead_out_knots.assign(at.begin() + static_cast<long>(cutLast) + 1, at.end());
    }
    return p;
}

} // namespace

std::shared_ptr<const MotionProgram> buildProfileCutterProgram(const Job& job,
                                                               const std::string& jobText) {
    ProfileLeads leads;
    if (job.process.used) {
        leads = computeProfileLeads(job, computeProfileCut(job));
        if (!leads.problem.empty()) throw std::invalid_argument(leads.problem);
    }
    return buildProfileCutterProgram(job, leads, jobText);
}

std::shared_ptr<const MotionProgram> buildProfileCutterProgram(const Job& job,
                                                               const ProfileLeads& leads,
                                                               const std::string& jobText,
                                                               ProfileProgramLayout* layout) {
    // A fine grid (the NC grid refined 8 times, at least 4096 points): the spline follows the
    // curve, not the chords of the stepper grid.
    const int fine = std::max(4096, 8 * profileCutterSpec(job).steps_per_rev_a);
    const ProfileCut cut = computeProfileCut(job, fine);
    const DevelopedPath path(cut);
    if (const std::string problem = travelProblem(job, cut); !problem.empty())
        throw std::invalid_argument(problem);
    if (!leads.used) return cutOnlyProgram(job, cut, path, jobText, layout);
    if (const std::string problem = leadTravelProblem(job, leads); !problem.empty())
        throw std::invalid_argument(problem);
    return leadProgram(job, cut, path, leads, jobText, layout);
}

json::Value profileRunReportJson(const TrackingReport& r) {
    auto axes = [](const std::array<AxisErrorStats, kMaxAxes>& j) {
        return json::Array{json::Object{{"axis", 0},
                                        {"name", "A (pipe turn)"},
                                        {"max_abs_error_deg", j[0].max_abs},
                                        {"rms_error_deg", j[0].rms}},
                           json::Object{{"axis", 1},
                                        {"name", "X (torch carriage)"},
                                        {"max_abs_error_mm", j[1].max_abs},
                                        {"rms_error_mm", j[1].rms}}};
    };
    auto vec = [](const Vec3& v) { return json::Object{{"x", v.x()}, {"y", v.y()}, {"z", v.z()}}; };
    return json::Object{
        {"machine", kProfileCutterId},
        {"length_mm", r.length_mm},
        {"cut_time_s", r.cut_time_s},
        {"simulated_s", r.simulated_s},
        {"steps", static_cast<double>(r.steps)},
        {"axes", axes(r.joints)},
        {"tip_on_pipe",
         json::Object{
             {"about",
              "torch tip on the pipe surface (work frame: pipe axis z), actual - commanded"},
             {"max_abs_error_mm", vec(r.cartesian_max_abs_mm)}}},
        {"cruise",
         json::Object{{"about", "constant cutting speed only (start and stop ramps excluded)"},
                      {"axes", axes(r.cruise_joints)},
                      {"tip_on_pipe_max_abs_error_mm", vec(r.cruise_cartesian_max_abs_mm)}}}};
}

} // namespace cutcell
