#include "core/pipe_joint/multi_branch.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace cutcell {

JointPipe jointPipeFrom(const OtherBranch& b) {
    const double a = deg2rad(b.angle_deg), ph = deg2rad(b.phase_deg);
    const Eigen::AngleAxisd rz(ph, Vec3::UnitZ());
    JointPipe p;
    p.axis_point = rz * Vec3(b.eccentricity_mm, 0, b.position_mm);
    p.axis_dir = (rz * Vec3(0, std::sin(a), std::cos(a))).normalized();
    p.radius_mm = b.radius_mm;
    return p;
}

// The other pipe's frame: z = its axis, x = b x z (common perpendicular, so the cut branch's
// axis lies in the plane x = e' with a positive y component, as PipeIntersection wants).
BranchCrossing::LocalFrame BranchCrossing::localFrame(const PipeIntersection& cut,
                                                      const JointPipe& pipe) {
    const Vec3 b = cut.branchAxis();
    const Vec3 z = pipe.axis_dir.normalized();
    const Vec3 bxz = b.cross(z);
    if (bxz.norm() < 1e-9)
        throw std::invalid_argument("a branch pipe is parallel to the cut branch: no crossing");
    const Vec3 x = bxz.normalized();
    const Vec3 y = z.cross(x);
    // Closest points of the two axes.
    const Vec3 w0 = cut.branchOrigin() - pipe.axis_point;
    const double bz = b.dot(z), d = b.dot(w0), e = z.dot(w0);
    const double denom = 1 - bz * bz;
    const double s = (bz * e - d) / denom, u = (e - bz * d) / denom;
    const Vec3 qb = cut.branchOrigin() + s * b;
    const Vec3 qj = pipe.axis_point + u * z;
    LocalFrame f{Pose::Identity(), IntersectionSpec{}};
    f.first.linear().col(0) = x;
    f.first.linear().col(1) = y;
    f.first.linear().col(2) = z;
    f.first.translation() = qj;
    f.second.main_radius_mm = pipe.radius_mm;
    f.second.branch_radius_mm = cut.spec().branch_radius_mm;
    f.second.angle_deg = rad2deg(std::atan2(b.dot(y), b.dot(z)));
    f.second.eccentricity_mm = (qb - qj).dot(x);
    return f;
}

namespace {

IntersectionSpec withSide(IntersectionSpec s, int side) {
    s.side = side;
    return s;
}

} // namespace

BranchCrossing::BranchCrossing(const PipeIntersection& cutBranch, const JointPipe& pipe,
                               double mainRadius)
    : BranchCrossing(cutBranch, pipe, mainRadius, localFrame(cutBranch, pipe)) {}

BranchCrossing::BranchCrossing(const PipeIntersection& cutBranch, const JointPipe& pipe,
                               double mainRadius, const LocalFrame& frame)
    : cut_(&cutBranch), pipe_(pipe), mainRadius_(mainRadius), mainFromLocal_(frame.first),
      localPlus_(withSide(frame.second, +1)), localMinus_(withSide(frame.second, -1)) {}

std::optional<Vec3> BranchCrossing::meet(double phi) const {
    // The generatrix's radial direction in the main frame, then its parameter in the local frame.
    const Vec3 u = std::sin(phi) * Vec3::UnitX() + std::cos(phi) * cut_->branchY();
    const Vec3 xLocal = mainFromLocal_.linear().col(0);
    const Vec3 nLocal = mainFromLocal_.linear() * localPlus_.branchY();
    const double phiLocal = std::atan2(u.dot(xLocal), u.dot(nLocal));
    if (!localPlus_.generatrixMeetsMain(phiLocal)) return std::nullopt;
    std::optional<Vec3> best;
    double bestT = -std::numeric_limits<double>::infinity();
    for (const PipeIntersection* local : {&localPlus_, &localMinus_}) {
        const Vec3 p = mainFromLocal_ * local->point(phiLocal);
        const bool onRealPart = (p - pipe_.axis_point).dot(pipe_.axis_dir) >= -1e-9;
        const bool outsideMain = std::hypot(p.x(), p.y()) >= mainRadius_ - 1e-9;
        const double t = (p - cut_->branchOrigin()).dot(cut_->branchAxis());
        if (onRealPart && outsideMain && t > bestT) {
            bestT = t;
            best = p;
        }
    }
    return best;
}

SetM buildSetM(const PipeIntersection& cutBranch, const std::vector<JointPipe>& others, double L_mm,
               int n, double phi0) {
    SetM m;
    m.rows = n;
    m.cols = 1 + static_cast<int>(others.size());
    m.L_mm = L_mm;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    m.phi_rad.resize(static_cast<size_t>(n));
    m.l.assign(static_cast<size_t>(n * m.cols), nan);
    m.point.assign(static_cast<size_t>(n * m.cols), Vec3::Constant(nan));
    std::vector<BranchCrossing> crossings;
    crossings.reserve(others.size());
    for (const auto& o : others)
        crossings.emplace_back(cutBranch, o, cutBranch.spec().main_radius_mm);
    const Vec3 origin = cutBranch.branchOrigin(), axis = cutBranch.branchAxis();
    for (int i = 0; i < n; ++i) {
        const double phi = phi0 + 2 * kPi * i / n;
        m.phi_rad[static_cast<size_t>(i)] = phi;
        const size_t row = static_cast<size_t>(i * m.cols);
        // Main pipe: the y > 0 root (side +1) is the peak, the one nearest the fixed end.
        m.point[row] = cutBranch.point(phi);
        m.l[row] = L_mm - (m.point[row] - origin).dot(axis);
        for (size_t k = 0; k < crossings.size(); ++k)
            if (const auto p = crossings[k].meet(phi)) {
                m.point[row + 1 + k] = *p;
                m.l[row + 1 + k] = L_mm - (*p - origin).dot(axis);
            }
    }
    return m;
}

ColumnMinima columnMinima(const SetM& m) {
    ColumnMinima out;
    const size_t n = static_cast<size_t>(m.rows);
    out.N.resize(n);
    out.c.resize(n);
    out.N_prime.resize(n);
    for (int i = 0; i < m.rows; ++i) {
        int best = 0; // the main pipe always meets (|e| + r <= R is validated)
        for (int j = 1; j < m.cols; ++j)
            if (std::isfinite(m.at(i, j)) && m.at(i, j) < m.at(i, best)) best = j;
        out.N[static_cast<size_t>(i)] = m.at(i, best);
        out.c[static_cast<size_t>(i)] = best;
    }
    for (size_t i = 0; i < n; ++i)
        out.N_prime[i] = out.N[(i + 1) % n] - out.N[i];
    return out;
}

} // namespace cutcell
