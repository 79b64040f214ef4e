#include "core/geometry/cut_path.h"

#include <algorithm>
#include <cmath>

namespace cutcell {

IntersectionSpec intersectionSpecFor(const Job& job) {
    IntersectionSpec s;
    s.main_radius_mm = job.main_pipe.radius_mm;
    // The hole must pass the branch's bore; the branch end lies on its outer surface.
    s.branch_radius_mm = job.cut.target == CutTarget::Main
                             ? job.branch_pipe.radius_mm - job.branch_pipe.wall_mm
                             : job.branch_pipe.radius_mm;
    s.angle_deg = job.angle_deg;
    s.eccentricity_mm = job.eccentricity_mm;
    s.side = +1;
    return s;
}

double startPhi(const Job& job) {
    if (!job.cut.start_phi_auto) return deg2rad(job.cut.start_phi_deg);
    return job.cut.target == CutTarget::Main ? -kPi / 2 : -kPi;
}

ArcLengthTable::ArcLengthTable(const PipeIntersection& curve, double phi0, int samples)
    : curve_(&curve), phi0_(phi0), dphi_(2 * kPi / samples), s_(static_cast<size_t>(samples) + 1) {
    // Simpson's rule on each sub-interval of |dP/dphi|.
    s_[0] = 0;
    for (int i = 0; i < samples; ++i) {
        const double a = phi0 + i * dphi_;
        const double fa = curve.derivative(a).norm();
        const double fm = curve.derivative(a + dphi_ / 2).norm();
        const double fb = curve.derivative(a + dphi_).norm();
        s_[static_cast<size_t>(i) + 1] =
            s_[static_cast<size_t>(i)] + dphi_ / 6 * (fa + 4 * fm + fb);
    }
    length_ = s_.back();
}

double ArcLengthTable::sAt(double phi) const {
    const double u = std::clamp((phi - phi0_) / dphi_, 0.0, static_cast<double>(s_.size() - 1));
    const size_t i = std::min(static_cast<size_t>(u), s_.size() - 2);
    const double a = phi0_ + static_cast<double>(i) * dphi_;
    // Simpson from the tabulated node to phi.
    const double h = phi - a;
    const double fa = curve_->derivative(a).norm();
    const double fm = curve_->derivative(a + h / 2).norm();
    const double fb = curve_->derivative(phi).norm();
    return s_[i] + h / 6 * (fa + 4 * fm + fb);
}

double ArcLengthTable::phiAt(double s) const {
    s = std::clamp(s, 0.0, length_);
    const auto it = std::upper_bound(s_.begin(), s_.end(), s);
    const size_t i = std::min<size_t>(
        static_cast<size_t>(std::max<std::ptrdiff_t>(it - s_.begin() - 1, 0)), s_.size() - 2);
    const double ds = s_[i + 1] - s_[i];
    double phi = phi0_ + dphi_ * (static_cast<double>(i) + (ds > 0 ? (s - s_[i]) / ds : 0));
    // Newton on s(phi) = s; ds/dphi = |P'(phi)|.
    for (int k = 0; k < 3; ++k) {
        const double speed = curve_->derivative(phi).norm();
        if (speed < 1e-12) break;
        phi -= (sAt(phi) - s) / speed;
    }
    return phi;
}

CutGeometry::CutGeometry(const Job& job)
    : curve_(intersectionSpecFor(job)), table_(curve_, startPhi(job)), target_(job.cut.target),
      workRadius_(job.cut.target == CutTarget::Main ? job.main_pipe.radius_mm
                                                    : job.branch_pipe.radius_mm),
      bevelDeg_(job.cut.bevel_deg), phi0_(startPhi(job)) {
    // Work frame axes in the main frame, then centre the cut at work z = 0.
    Mat3 axes = Mat3::Identity();
    Vec3 origin = Vec3::Zero();
    if (target_ == CutTarget::Branch) {
        axes.col(0) = Vec3::UnitX();
        axes.col(1) = curve_.branchY();
        axes.col(2) = curve_.branchAxis();
        origin = curve_.branchOrigin();
    }
    double zmin = 1e300, zmax = -1e300;
    Vec3 centre = Vec3::Zero();
    const int n = 720;
    for (int i = 0; i < n; ++i) {
        const Vec3 p = curve_.point(phi0_ + 2 * kPi * i / n);
        const double z = (p - origin).dot(axes.col(2));
        zmin = std::min(zmin, z);
        zmax = std::max(zmax, z);
        centre += p / n;
    }
    origin += axes.col(2) * (zmin + zmax) / 2;
    mainFromWork_ = Pose::Identity();
    mainFromWork_.linear() = axes;
    mainFromWork_.translation() = origin;
    holeCentreWork_ = mainFromWork_.inverse() * centre;
}

CutPoint CutGeometry::atPhi(double phi) const {
    CutPoint c;
    c.phi_rad = phi;
    c.s_mm = table_.sAt(phi);
    c.p_main = curve_.point(phi);
    const Pose workFromMain = mainFromWork_.inverse();
    c.p_work = workFromMain * c.p_main;
    c.tangent_work = (workFromMain.linear() * curve_.derivative(phi)).normalized();
    c.normal_work = -Vec3(c.p_work.x(), c.p_work.y(), 0).normalized();
    // Side of the cut that is scrap: the hole's inside, or for the branch end the part
    // toward the main pipe (-z of the work frame). A positive bevel leans the torch that way,
    // which leaves a V-groove edge on the part that is kept.
    Vec3 side = c.normal_work.cross(c.tangent_work).normalized();
    const Vec3 toScrap =
        target_ == CutTarget::Main ? Vec3(holeCentreWork_ - c.p_work) : Vec3(-Vec3::UnitZ());
    if (side.dot(toScrap) < 0) side = -side;
    const double bev = deg2rad(bevelDeg_);
    c.approach_work = (std::cos(bev) * c.normal_work + std::sin(bev) * side).normalized();
    return c;
}

CutPoint CutGeometry::atArcLength(double s) const {
    CutPoint c = atPhi(table_.phiAt(s));
    c.s_mm = s;
    return c;
}

std::vector<CutPoint> CutGeometry::sampleEqualArcLength(double spacing_mm) const {
    const int n = std::max(8, static_cast<int>(std::ceil(length() / spacing_mm)));
    std::vector<CutPoint> pts;
    pts.reserve(static_cast<size_t>(n) + 1);
    for (int i = 0; i <= n; ++i)
        pts.push_back(atArcLength(length() * i / n));
    return pts;
}

std::vector<CutPoint> CutGeometry::sampleByPhi(int count) const {
    std::vector<CutPoint> pts;
    pts.reserve(static_cast<size_t>(count) + 1);
    for (int i = 0; i <= count; ++i)
        pts.push_back(atPhi(phi0_ + 2 * kPi * i / count));
    return pts;
}

} // namespace cutcell
