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

std::shared_ptr<const MotionProgram> buildProfileCutterProgram(const Job& job,
                                                               const std::string& jobText) {
    // A fine grid (the NC grid refined 8 times, at least 4096 points): the spline follows the
    // curve, not the chords of the stepper grid.
    const int fine = std::max(4096, 8 * profileCutterSpec(job).steps_per_rev_a);
    const ProfileCut cut = computeProfileCut(job, fine);
    const DevelopedPath path(cut);
    if (const std::string problem = travelProblem(job, cut); !problem.empty())
        throw std::invalid_argument(problem);

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

    auto p = std::make_shared<MotionProgram>();
    p->machine = kProfileCutterId;
    p->method = "rotating_pipe";
    p->axis_count = 2;
    p->axis_names = {"A (pipe turn)", "X (torch carriage)", "", "", "", ""};
    p->axis_linear = {false, true, false, false, false, false};
    p->reference = JointVector::Zero();
    p->reference[1] = knots.front()[1]; // A at 0, the torch over the start's X
    p->min_position[1] = 0;
    p->max_position[1] = profileCutterSpec(job).x_travel_mm;
    p->spline = JointSpline(std::move(knots), dt);
    p->cut_time_s = cutTime;
    p->length_mm = path.length();
    p->point_count = static_cast<size_t>(intervals) + 1;
    p->tip_model = std::make_shared<ProfileCutterTipModel>(cut.work_radius_mm);
    const double ramp = cutTime - path.length() / job.cut.speed_mm_s;
    p->cruise_from_s = ramp;
    p->cruise_to_s = cutTime - ramp;
    p->pierce_s = profileCutterSpec(job).pierce_s; // as the G-code's G4 after M3
    p->name = job.name;
    p->source_text = jobText.empty() ? json::write(jobToJson(job)) : jobText;
    return p;
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
