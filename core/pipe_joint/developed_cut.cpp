#include "core/pipe_joint/developed_cut.h"
#include "core/common/c_format.h"

#include "core/geometry/cut_path.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cutcell {

IntersectionSpec profileIntersectionSpec(const Job& job) {
    return intersectionSpecFor(job);
}

std::vector<JointPipe> jointPipes(const JointExtras& extras) {
    std::vector<JointPipe> out;
    for (const auto& b : extras.other_branches)
        out.push_back(jointPipeFrom(b));
    return out;
}

double ProfileCut::developedLength() const {
    double len = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        const ProfilePoint a = closedAt(i), b = closedAt(i + 1);
        len += std::hypot(b.x_mm - a.x_mm, work_radius_mm * deg2rad(b.a_deg - a.a_deg));
    }
    return len;
}

ProfilePoint ProfileCut::closedAt(size_t i) const {
    if (i < points.size()) return points[i];
    ProfilePoint p = points[i % points.size()];
    p.a_deg += a_per_turn_deg * static_cast<double>(i / points.size());
    return p;
}

namespace {

// Beta = 0 at the start, so phi0 = 90 deg (see the mapping in multi_branch.h).
constexpr double kPhi0 = kPi / 2;

// The seed's N at one rotation angle (L = 0).
double minimumAt(const PipeIntersection& cut, const std::vector<JointPipe>& pipes, double phi) {
    return columnMinima(buildSetM(cut, pipes, 0.0, 1, phi)).N.front();
}

// max over phi of N(phi): a dense scan, then a golden-section search around the best sample.
double longestGeneratrix(const PipeIntersection& cut, const std::vector<JointPipe>& pipes) {
    constexpr int kScan = 4096;
    const ColumnMinima scan = columnMinima(buildSetM(cut, pipes, 0.0, kScan, 0.0));
    const auto best = std::max_element(scan.N.begin(), scan.N.end());
    const double h = 2 * kPi / kScan;
    double a = h * static_cast<double>(best - scan.N.begin()) - h, b = a + 2 * h;
    const double g = (std::sqrt(5.0) - 1) / 2;
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = minimumAt(cut, pipes, c), fd = minimumAt(cut, pipes, d);
    for (int i = 0; i < 60 && b - a > 1e-12; ++i) {
        if (fc > fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = minimumAt(cut, pipes, c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = minimumAt(cut, pipes, d);
        }
    }
    return std::max({*best, fc, fd});
}

ProfileCut branchEnd(const Job& job, const JointExtras& extras, int n) {
    const PipeIntersection cut(profileIntersectionSpec(job));
    const SetM m = buildSetM(cut, jointPipes(extras), 0.0, n, kPhi0);
    const ColumnMinima mins = columnMinima(m);
    // With L = 0, l = -t; the longest generatrix (largest l) becomes branch_pipe.length_mm,
    // found independently of n so every grid (NC, template, engine) gives the same X.
    const double shift = job.branch_pipe.length_mm - longestGeneratrix(cut, jointPipes(extras));
    ProfileCut out;
    out.target = CutTarget::Branch;
    out.work_radius_mm = job.branch_pipe.radius_mm;
    out.a_per_turn_deg = 360;
    for (int i = 0; i < n; ++i) {
        const size_t k = static_cast<size_t>(i);
        ProfilePoint p;
        p.phi_rad = m.phi_rad[k];
        p.beta_deg = 360.0 * i / n;
        p.a_deg = p.beta_deg;
        p.x_mm = mins.N[k] + shift;
        p.pipe = mins.c[k];
        p.p_main = m.pointAt(i, p.pipe);
        out.points.push_back(p);
    }
    out.increments_x_mm = mins.N_prime;
    return out;
}

ProfileCut mainHole(const Job& job, const JointExtras& extras, int n) {
    const PipeIntersection cut(profileIntersectionSpec(job));
    const double S =
        extras.branch_position_auto ? job.main_pipe.length_mm / 2 : extras.branch_position_mm;
    ProfileCut out;
    out.target = CutTarget::Main;
    out.work_radius_mm = job.main_pipe.radius_mm;
    out.a_per_turn_deg = 0;
    for (int i = 0; i < n; ++i) {
        ProfilePoint p;
        p.phi_rad = kPhi0 + 2 * kPi * i / n;
        p.beta_deg = 360.0 * i / n;
        p.p_main = cut.point(p.phi_rad);
        // alpha from the top of the main pipe (+y, the branch side); within (-90, 90) deg.
        p.a_deg = rad2deg(std::atan2(p.p_main.x(), p.p_main.y()));
        p.x_mm = S + p.p_main.z();
        out.points.push_back(p);
    }
    for (size_t i = 0; i < out.points.size(); ++i)
        out.increments_x_mm.push_back(out.closedAt(i + 1).x_mm - out.points[i].x_mm);
    return out;
}

} // namespace

ProfileCut computeProfileCut(const Job& job, const JointExtras& extras, int n) {
    return job.cut.target == CutTarget::Branch ? branchEnd(job, extras, n)
                                               : mainHole(job, extras, n);
}

} // namespace cutcell
