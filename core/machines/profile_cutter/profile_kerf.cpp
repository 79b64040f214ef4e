#include "core/machines/profile_cutter/profile_kerf.h"

#include "core/process/kerf_offset.h"

#include <cmath>

namespace cutcell {
namespace {

// The developed coordinates on the work pipe's surface as a point of the work frame: the pipe
// axis is z (= X), A is measured from +y toward +x (as the hole's alpha = atan2(x, y)).
Vec3 surfacePoint(double radius, double x_mm, double a_deg) {
    const double a = deg2rad(a_deg);
    return {radius * std::sin(a), radius * std::cos(a), x_mm};
}

// The cut as CutPoints of the work frame (closed: the first point repeated one turn later),
// tangents from the neighbours, torch axes along the inward radius.
std::vector<CutPoint> workPoints(const ProfileCut& cut) {
    const size_t n = cut.points.size();
    std::vector<CutPoint> out(n + 1);
    for (size_t i = 0; i <= n; ++i) {
        const ProfilePoint p = cut.closedAt(i);
        CutPoint& c = out[i];
        c.phi_rad = p.phi_rad;
        c.p_work = surfacePoint(cut.work_radius_mm, p.x_mm, p.a_deg);
        c.p_main = c.p_work;
        c.normal_work = -Vec3(c.p_work.x(), c.p_work.y(), 0).normalized();
        c.approach_work = c.normal_work;
    }
    double s = 0;
    for (size_t i = 0; i <= n; ++i) {
        // Neighbours on the closed curve (i = 0 and i = n are the same point; A and A + 360
        // deg are the same place on the pipe).
        const ProfilePoint prev = cut.closedAt(i == 0 ? n - 1 : i - 1);
        const ProfilePoint next = cut.closedAt(i + 1);
        const Vec3 t = surfacePoint(cut.work_radius_mm, next.x_mm, next.a_deg) -
                       surfacePoint(cut.work_radius_mm, prev.x_mm, prev.a_deg);
        // A torch path carries its edge's tangents: the inverse uses them, not its own.
        const Vec3& kept = cut.points[i % n].edge_tangent;
        out[i].tangent_work = kept.squaredNorm() > 0 ? kept : t.normalized();
        if (i > 0) s += (out[i].p_work - out[i - 1].p_work).norm();
        out[i].s_mm = s;
    }
    return out;
}

// Left of the travel seen from outside (outward normal x tangent) is scrap when it points, on
// the whole, toward +X (branch end) or toward the hole's middle.
ScrapSide scrapSide(const ProfileCut& cut, const std::vector<CutPoint>& pts) {
    Vec3 middle = Vec3::Zero();
    for (size_t i = 0; i + 1 < pts.size(); ++i)
        middle += Vec3(0, 0, pts[i].p_work.z());
    middle /= static_cast<double>(pts.size() - 1);
    double meanA = 0;
    for (const ProfilePoint& p : cut.points)
        meanA += p.a_deg;
    meanA /= static_cast<double>(cut.points.size());
    double vote = 0;
    for (size_t i = 0; i + 1 < pts.size(); ++i) {
        const CutPoint& c = pts[i];
        const Vec3 left = (-c.normal_work).cross(c.tangent_work);
        Vec3 toScrap = Vec3::UnitZ();
        if (cut.target == CutTarget::Main) {
            // Toward the hole's middle along the surface: axially and around.
            const Vec3 around = Vec3(c.p_work.y(), -c.p_work.x(), 0).normalized(); // +A
            const double a = rad2deg(std::atan2(c.p_work.x(), c.p_work.y()));
            toScrap = (middle.z() - c.p_work.z()) * Vec3::UnitZ() +
                      cut.work_radius_mm * deg2rad(meanA - a) * around;
        }
        vote += left.dot(toScrap);
    }
    return vote >= 0 ? ScrapSide::Left : ScrapSide::Right;
}

Outcome shiftCut(ProfileCut& cut, double kerf_mm, bool toTorch) {
    if (cut.points.size() < 3) return Outcome::refuse("the cut has fewer than 3 points");
    const std::vector<CutPoint> pts = workPoints(cut);
    KerfPathSpec spec;
    spec.work_radius_mm = cut.work_radius_mm;
    spec.scrap = scrapSide(cut, pts);
    spec.closed = true;
    const KerfPath moved =
        toTorch ? offsetCutPath(spec, pts, kerf_mm) : edgeFromTorchPath(spec, pts, kerf_mm);
    if (!moved.outcome.ok()) return moved.outcome;
    for (size_t i = 0; i < cut.points.size(); ++i) {
        ProfilePoint& p = cut.points[i];
        const Vec3& q = moved.points[i].p_work;
        const double a = rad2deg(std::atan2(q.x(), q.y()));
        // Continuous A: the turn nearest the edge's.
        p.a_deg = a + 360.0 * std::round((p.a_deg - a) / 360.0);
        p.x_mm = q.z();
        p.edge_tangent = toTorch ? pts[i].tangent_work : Vec3::Zero();
    }
    cut.increments_x_mm.clear();
    for (size_t i = 0; i < cut.points.size(); ++i)
        cut.increments_x_mm.push_back(cut.closedAt(i + 1).x_mm - cut.points[i].x_mm);
    return Outcome::done();
}

} // namespace

Outcome compensateProfileKerf(ProfileCut& cut, double kerf_mm) {
    if (kerf_mm == 0) return Outcome::done();
    const Outcome o = shiftCut(cut, kerf_mm, true);
    if (o.ok()) cut.kerf_mm = kerf_mm;
    return o;
}

bool profileScrapOnLeft(const ProfileCut& cut) {
    return scrapSide(cut, workPoints(cut)) == ScrapSide::Left;
}

Outcome profileEdgeFromTorch(ProfileCut& torch) {
    if (torch.kerf_mm == 0) return Outcome::done();
    const Outcome o = shiftCut(torch, torch.kerf_mm, false);
    if (o.ok()) torch.kerf_mm = 0;
    return o;
}

} // namespace cutcell
