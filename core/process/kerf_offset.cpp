#include "core/process/kerf_offset.h"

#include "core/common/c_format.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace cutcell {

namespace {

constexpr double kMaxHalfKerfOverRadius = 0.1;    // k/2 <= 0.1 R (header: the skin's bend)
constexpr double kMaxHalfKerfOverCurvature = 0.5; // k/2 <= 0.5 / curvature toward scrap
constexpr double kMinTorchTangentDeg = 10;        // torch axis vs tangent
constexpr double kMinCutToSurfaceDeg = 1;         // cut surface vs pipe surface

// The kerf as a number: finite and >= 0 mm.
Outcome checkKerfValue(double kerf_mm) {
    if (!std::isfinite(kerf_mm))
        return Outcome::refuse(messageC("the kerf %.6g mm is not a finite number", kerf_mm));
    if (kerf_mm < 0)
        return Outcome::refuse(
            messageC("the kerf %.6g mm is negative: it must be 0 mm or more", kerf_mm));
    return Outcome::done();
}

Outcome checkKerf(double kerf_mm, double radius_mm) {
    if (Outcome o = checkKerfValue(kerf_mm); !o.ok()) return o;
    const double limit = 2 * kMaxHalfKerfOverRadius * radius_mm;
    if (kerf_mm > limit)
        return Outcome::refuse(messageC("the kerf %.6g mm is too wide for a pipe of radius %.6g "
                                        "mm: at most %.6g mm (0.2 x the radius)",
                                        kerf_mm, radius_mm, limit));
    return Outcome::done();
}

// The root s nearest 0 of |x0 + s m - axis| = radius (closed form; the stable quadratic roots,
// so that x0 on the surface gives s = 0 to rounding).
std::optional<double> surfaceCrossing(const PipeSurface& c, const Vec3& x0, const Vec3& m) {
    const Vec3& u = c.axis_dir;
    const Vec3 w = x0 - c.axis_point;
    const Vec3 wr = w - w.dot(u) * u;
    const Vec3 mr = m - m.dot(u) * u;
    const double A = mr.squaredNorm(), B = 2 * wr.dot(mr),
                 C = wr.squaredNorm() - c.radius_mm * c.radius_mm;
    const double disc = B * B - 4 * A * C;
    if (A < 1e-12 || disc < 0) return std::nullopt;
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    if (q == 0) return 0.0; // B = C = 0: x0 on the surface, m through the axis
    const double s1 = q / A, s2 = C / q;
    return std::fabs(s1) < std::fabs(s2) ? s1 : s2;
}

// The cut surface's unit normal *n (the plane of the unit edge tangent t and the torch axis d),
// or the refusal when the torch is too close to the tangent to make a surface.
Outcome cutSurfaceNormal(const Vec3& t, const Vec3& dIn, Vec3* n) {
    const Vec3 txd = t.cross(dIn.normalized());
    // |t x d| = sin of the angle between them (NaN for a zero vector: refused as well).
    const double sinTd = txd.norm();
    if (!(sinTd >= std::sin(deg2rad(kMinTorchTangentDeg))))
        return Outcome::refuse(messageC("the torch axis is %.6g deg from the edge's tangent: "
                                        "at least %.6g deg is needed for a cut surface",
                                        rad2deg(std::asin(std::min(1.0, sinTd))),
                                        kMinTorchTangentDeg));
    *n = txd / sinTd;
    return {};
}

// Offset p by `across` (signed, along n toward scrap) within p's cross-section plane, onto the
// surface. The one construction for both directions.
KerfPoint shift(const PipeSurface& pipe, const Vec3& p, const Vec3& tIn, const Vec3& dIn,
                ScrapSide scrap, double kerf_mm, double sign) {
    KerfPoint r;
    r.outcome = checkKerf(kerf_mm, pipe.radius_mm);
    if (!r.outcome.ok()) return r;
    const Vec3 t = tIn.normalized();
    Vec3 n;
    if (Outcome o = cutSurfaceNormal(t, dIn, &n); !o.ok()) return {o};
    // The pipe's outward normal at p and the across direction on the surface toward scrap;
    // n . across = sin of the angle between the cut surface and the pipe surface.
    const Vec3 w = p - pipe.axis_point;
    const Vec3 up = (w - w.dot(pipe.axis_dir) * pipe.axis_dir).normalized();
    const Vec3 across = static_cast<double>(static_cast<int>(scrap)) * up.cross(t).normalized();
    const double side = n.dot(across);
    if (!(std::fabs(side) >= std::sin(deg2rad(kMinCutToSurfaceDeg))))
        return {Outcome::refuse(messageC("the cut surface is %.6g deg from the pipe surface: at "
                                         "least %.6g deg is needed to tell its sides",
                                         rad2deg(std::asin(std::min(1.0, std::fabs(side)))),
                                         kMinCutToSurfaceDeg))};
    if (side < 0) n = -n;
    const Vec3 m = n.cross(t);
    const Vec3 x0 = p + sign * kerf_mm / 2 * n;
    const auto s = surfaceCrossing(pipe, x0, m);
    if (!s)
        return {Outcome::refuse(messageC("the torch line %.6g mm off the edge misses the pipe "
                                         "surface of radius %.6g mm",
                                         kerf_mm / 2, pipe.radius_mm))};
    r.point = x0 + *s * m;
    r.across = n;
    r.along_surface_mm = (r.point - p).norm();
    return r;
}

constexpr double kMaxCutNormalToLinesDeg = 80; // prism: n . lines >= cos 80 deg (header)

// offsetOnPrism / edgeOnPrism: the point moved by sign k/2 across the cut surface along the lines.
KerfPoint shiftOnPrism(const Vec3& p, const Vec3& tIn, const Vec3& dIn, const Vec3& linesIn,
                       const Vec3& towardScrap, double kerf_mm, double sign) {
    KerfPoint r;
    r.outcome = checkKerfValue(kerf_mm);
    if (!r.outcome.ok()) return r;
    const Vec3 t = tIn.normalized(), lines = linesIn.normalized();
    Vec3 n;
    if (Outcome o = cutSurfaceNormal(t, dIn, &n); !o.ok()) return {o};
    const double side = n.dot(towardScrap.normalized());
    if (!(std::fabs(side) >= std::sin(deg2rad(kMinCutToSurfaceDeg))))
        return {Outcome::refuse(messageC("the cut surface is %.6g deg from the direction of the "
                                         "scrap side: at least %.6g deg is needed to tell its "
                                         "sides",
                                         rad2deg(std::asin(std::min(1.0, std::fabs(side)))),
                                         kMinCutToSurfaceDeg))};
    if (side < 0) n = -n;
    const double across = n.dot(lines);
    if (!(std::fabs(across) >= std::cos(deg2rad(kMaxCutNormalToLinesDeg))))
        return {Outcome::refuse(messageC("the cut surface's normal is %.6g deg from the surface's "
                                         "lines (the bar axis): at most %.6g deg, else the torch "
                                         "runs more than %.3g x k/2 along them",
                                         rad2deg(std::acos(std::min(1.0, std::fabs(across)))),
                                         kMaxCutNormalToLinesDeg,
                                         1 / std::cos(deg2rad(kMaxCutNormalToLinesDeg))))};
    r.point = p + sign * kerf_mm / 2 / across * lines;
    r.across = n;
    r.along_surface_mm = (r.point - p).norm();
    return r;
}

// Curvature vector at b of the circle through a, b, c (its length 1/radius, toward the
// centre), from the chords' unit directions.
Vec3 curvature(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double span = (c - a).norm();
    if (span < 1e-12) return Vec3::Zero();
    return 2 * ((c - b).normalized() - (b - a).normalized()) / span;
}

KerfPath shiftPath(const KerfPathSpec& spec, const std::vector<CutPoint>& in, double kerf_mm,
                   double sign) {
    KerfPath out;
    out.outcome = checkKerf(kerf_mm, spec.work_radius_mm);
    if (!out.outcome.ok()) return out;
    const PipeSurface pipe{Vec3::Zero(), Vec3::UnitZ(), spec.work_radius_mm};
    const size_t N = in.size();
    // A closed path that repeats its first point has N - 1 distinct points; neighbours wrap.
    const bool repeat =
        spec.closed && N > 2 && (in.front().p_work - in.back().p_work).norm() < 1e-9;
    const size_t U = repeat ? N - 1 : N;
    out.points = in;
    for (size_t i = 0; i < N; ++i) {
        const CutPoint& c = in[i];
        const KerfPoint k =
            shift(pipe, c.p_work, c.tangent_work, c.approach_work, spec.scrap, kerf_mm, sign);
        if (!k.outcome.ok()) {
            out.outcome = Outcome::refuse(
                messageC("at %.6g mm along the cut: %s", c.s_mm, k.outcome.message.c_str()));
            out.points.clear();
            return out;
        }
        // The edge's curvature toward the scrap side, from the edge's neighbours (offsetting
        // only: going back, the input is the torch path, and its edge was checked when made).
        const size_t j = i % U;
        if (sign > 0 && U >= 3 && (spec.closed || (j > 0 && j + 1 < U))) {
            const Vec3& prev = in[(j + U - 1) % U].p_work;
            const Vec3& next = in[(j + 1) % U].p_work;
            const double kappa = curvature(prev, c.p_work, next).dot(k.across);
            if (kappa > 0 && kerf_mm / 2 > kMaxHalfKerfOverCurvature / kappa) {
                out.outcome = Outcome::refuse(messageC(
                    "the kerf %.6g mm is too wide for the edge at %.6g mm along the cut: its "
                    "radius of curvature toward the scrap side is %.6g mm, the kerf may be at "
                    "most %.6g mm",
                    kerf_mm, c.s_mm, 1 / kappa, 2 * kMaxHalfKerfOverCurvature / kappa));
                out.points.clear();
                return out;
            }
        }
        out.points[i].p_work = k.point;
        out.points[i].p_main = spec.main_from_work * k.point;
        if (kerf_mm > 0)
            out.max_stretch = std::max(out.max_stretch, k.along_surface_mm / (kerf_mm / 2));
    }
    return out;
}

} // namespace

KerfPoint offsetEdgePoint(const PipeSurface& pipe, const Vec3& p, const Vec3& t, const Vec3& d,
                          ScrapSide scrap, double kerf_mm) {
    return shift(pipe, p, t, d, scrap, kerf_mm, +1);
}

KerfPoint edgeFromTorchPoint(const PipeSurface& pipe, const Vec3& q, const Vec3& t, const Vec3& d,
                             ScrapSide scrap, double kerf_mm) {
    return shift(pipe, q, t, d, scrap, kerf_mm, -1);
}

KerfPoint offsetOnPrism(const Vec3& p, const Vec3& t, const Vec3& d, const Vec3& lines,
                        const Vec3& towardScrap, double kerf_mm) {
    return shiftOnPrism(p, t, d, lines, towardScrap, kerf_mm, +1);
}

KerfPoint edgeOnPrism(const Vec3& q, const Vec3& t, const Vec3& d, const Vec3& lines,
                      const Vec3& towardScrap, double kerf_mm) {
    return shiftOnPrism(q, t, d, lines, towardScrap, kerf_mm, -1);
}

KerfPath offsetCutPath(const KerfPathSpec& spec, const std::vector<CutPoint>& edge,
                       double kerf_mm) {
    return shiftPath(spec, edge, kerf_mm, +1);
}

KerfPoint offsetCutPoint(const KerfPathSpec& spec, CutPoint& c, double kerf_mm) {
    KerfPoint k;
    k.outcome = checkKerf(kerf_mm, spec.work_radius_mm);
    if (!k.outcome.ok()) return k;
    const PipeSurface pipe{Vec3::Zero(), Vec3::UnitZ(), spec.work_radius_mm};
    k = shift(pipe, c.p_work, c.tangent_work, c.approach_work, spec.scrap, kerf_mm, +1);
    if (!k.outcome.ok()) return k;
    c.p_work = k.point;
    c.p_main = spec.main_from_work * k.point;
    return k;
}

KerfPath edgeFromTorchPath(const KerfPathSpec& spec, const std::vector<CutPoint>& torch,
                           double kerf_mm) {
    return shiftPath(spec, torch, kerf_mm, -1);
}

KerfPathSpec kerfPathSpecFor(const Job& job, const CutGeometry& g) {
    KerfPathSpec s;
    s.work_radius_mm = g.workRadius();
    s.main_from_work = g.mainFromWork();
    s.closed = true;
    // The other pipe's axis in the work frame: the branch axis for the hole, the main axis for
    // the branch end. Its direction from each edge point, along "left", summed over the cut.
    const Pose workFromMain = g.mainFromWork().inverse();
    const bool hole = job.cut.target == CutTarget::Main;
    const Vec3 o = workFromMain * (hole ? g.curve().branchOrigin() : Vec3::Zero());
    const Vec3 u = workFromMain.linear() * (hole ? g.curve().branchAxis() : Vec3::UnitZ());
    double vote = 0;
    for (const CutPoint& c : g.sampleByPhi(360)) {
        const Vec3 toAxis = (o - c.p_work) - (o - c.p_work).dot(u) * u;
        vote += toAxis.normalized().dot((-c.normal_work).cross(c.tangent_work));
    }
    s.scrap = vote >= 0 ? ScrapSide::Left : ScrapSide::Right;
    return s;
}

} // namespace cutcell
