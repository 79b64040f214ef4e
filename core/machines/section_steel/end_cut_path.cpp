#include "core/machines/section_steel/end_cut_path.h"
#include "core/common/c_format.h"

#include "core/trajectory/speed_profile.h"

#include <algorithm>
#include <cmath>

namespace cutcell::section_steel {
namespace {

// A stretch of the pass: along the outline, or a turn of the torch at a sharp corner.
struct Primitive {
    bool turn = false;
    double s0 = 0, s1 = 0; // outline length (travel); s0 = the corner (turn)
    double a0 = 0, da = 0; // normal angle at the start and its change (turn)
    double effective = 0;  // length equivalent at the cutting speed
    size_t segment = 0;    // outline segment travelled (travel)
    // The tip's path length (mm, world): the outline's length in the (mitred) cut plane, with
    // the bevel's offset across the face where the groove's tilt ramps.
    double length = 0;
    // The time law where the world path is not a uniform image of the outline (a radius or a
    // torch turn in a mitred plane, a groove pass): the effective length at f = i / n of the
    // stretch (s0 .. s1 or a0 .. a0 + da), n = table.size() - 1; empty: effective * f.
    std::vector<double> table;
};

Primitive travelOf(double s0, double s1, double effective, size_t segment) {
    Primitive p;
    p.s0 = s0;
    p.s1 = s1;
    p.effective = effective;
    p.segment = segment;
    return p;
}

Primitive turnOf(double s, double a0, double da, double effective) {
    Primitive p;
    p.turn = true;
    p.s0 = s;
    p.a0 = a0;
    p.da = da;
    p.effective = effective;
    return p;
}

// The fraction f of a stretch at effective length e along it.
double fractionAt(const Primitive& p, double e) {
    if (p.table.empty()) return p.effective > 0 ? std::clamp(e / p.effective, 0.0, 1.0) : 0;
    const std::vector<double>& c = p.table;
    if (e <= c.front()) return 0;
    if (e >= c.back()) return 1;
    const size_t i = static_cast<size_t>(std::upper_bound(c.begin(), c.end(), e) - c.begin()) - 1;
    const double span = c[i + 1] - c[i];
    const double u = span > 0 ? std::clamp((e - c[i]) / span, 0.0, 1.0) : 0;
    return (static_cast<double>(i) + u) / static_cast<double>(c.size() - 1);
}

double angleOf(const Vec2& v) {
    return std::atan2(v.y(), v.x());
}

} // namespace

const char* toString(GrooveType g) {
    switch (g) {
    case GrooveType::None:
        return "none";
    case GrooveType::V:
        return "V";
    case GrooveType::Y:
        return "Y";
    case GrooveType::K:
        return "K";
    }
    return "?";
}

namespace {
// Turned over 180 deg about x, the bar's cut plane x = y tanV + (z - h/2) tanH reads, in the
// turned coordinates y' = -y, z' = h - z: x = y' (-tanV) + (z' - h/2) (-tanH).
double turnSign(const SectionSteelSpec& s) {
    return s.cut.setup == 2 ? -1.0 : 1.0;
}
} // namespace

EndCut::EndCut(const SectionSteelSpec& spec)
    : spec_(spec), outline_(spec.section, spec.cut.setup == 2),
      tanV_(turnSign(spec) * std::tan(deg2rad(spec.cut.mitre_vertical_deg))),
      tanH_(turnSign(spec) * std::tan(deg2rad(spec.cut.mitre_horizontal_deg))),
      square_(spec.cut.mitre_vertical_deg == 0 && spec.cut.mitre_horizontal_deg == 0) {}

bool EndCut::turnedOver() const {
    return outline_.turnedOver();
}

double EndCut::planeX(double y, double z) const {
    return y * tanV_ + (z - spec_.section.h_mm / 2) * tanH_;
}

Vec3 EndCut::planeNormal() const {
    return Vec3(1, -tanV_, -tanH_).normalized();
}

const GrooveSpec* EndCut::grooveOf(size_t segment) const {
    const OutlineSegment& g = outline_.segments()[segment];
    const GrooveSpec* s = g.kind == FaceKind::Flange ? &spec_.cut.flanges
                          : g.kind == FaceKind::Web  ? &spec_.cut.web
                                                     : nullptr;
    if (!s || s->type == GrooveType::None) return nullptr;
    // Turned over (setup 2): only what setup 1 could not reach, the K groove's second bevel on
    // the face that lay on the table; the other faces were bevelled in setup 1.
    if (turnedOver()) return g.former_table_face && s->type == GrooveType::K ? s : nullptr;
    if ((s->type == GrooveType::V || s->type == GrooveType::Y) && !g.groove_side) return nullptr;
    return s;
}

bool EndCut::hasGroove() const {
    for (size_t i = 0; i < outline_.segments().size(); ++i)
        if (grooveOf(i)) return true;
    return false;
}

double EndCut::tiltAt(size_t segment, double s, double* depth) const {
    *depth = 0;
    const GrooveSpec* gs = grooveOf(segment);
    if (!gs) return 0;
    const OutlineSegment& g = outline_.segments()[segment];
    const double u = s - outline_.segmentStart(segment);
    const double blend = std::max(1e-9, spec_.blend_mm);
    const double ramp = std::clamp(std::min(u, g.length - u) / blend, 0.0, 1.0);
    const double T = g.thickness_mm;
    switch (gs->type) {
    case GrooveType::V:
        *depth = T;
        break;
    case GrooveType::Y:
        *depth = T - gs->root_face_mm;
        break;
    case GrooveType::K:
        *depth = (T - gs->root_face_mm) / 2;
        break;
    case GrooveType::None:
        break;
    }
    return ramp * deg2rad(gs->angle_deg);
}

TorchTarget EndCut::target(const OutlinePoint& o, double s, bool groovePass) const {
    TorchTarget t;
    t.yz = o.p;
    t.s_mm = s;
    t.segment = o.segment;
    const Vec3 m = planeNormal();
    const Vec3 N(0, o.normal.x(), o.normal.y());
    const Vec2& d = o.tangent;
    t.edge = Vec3(d.x() * tanV_ + d.y() * tanH_, d.x(), d.y()).normalized();
    Vec3 u = m.cross(t.edge).normalized();
    if (u.dot(N) > 0) u = -u;
    t.t0 = u;
    double depth = 0;
    t.tilt_rad = groovePass ? tiltAt(o.segment, s, &depth) : 0;
    t.t = std::cos(t.tilt_rad) * u + std::sin(t.tilt_rad) * m;
    t.p = Vec3(planeX(o.p.x(), o.p.y()), o.p.x(), o.p.y());
    if (t.tilt_rad != 0) {
        // The bevel starts on the face, D tan(beta) before the cut plane, so that the bevel
        // face meets the cut plane at the depth D of the groove (V: T, Y: T - c, K: (T - c)/2).
        Vec3 w = N.cross(t.edge).normalized();
        if (w.dot(m) < 0) w = -w;
        t.p -= depth * std::tan(t.tilt_rad) / w.dot(m) * w;
    }
    t.edge_p = t.p; // the kerf compensation moves p only (section_kerf.h)
    return t;
}

void EndCut::applyLean(CutPass& pass, double dt) const {
    const TorchBody body = torchBody();
    const bool offcut = pass.name == "square";
    const size_t n = pass.samples.size();
    const double step = deg2rad(2), maxLean = deg2rad(spec_.max_lean_deg);
    std::vector<double> pos(n, 0), neg(n, 0); // required lean either way (0: none)
    double prefer = 1;
    bool any = false;
    for (size_t k = 0; k < n; ++k) {
        const TorchTarget& t = pass.samples[k];
        if (!torchHit(*this, body, t.p, t.t, offcut)) continue;
        for (double lean = step; lean <= maxLean + 1e-12; lean += step) {
            bool found = false;
            for (double sign : {prefer, -prefer}) {
                const Vec3 leaned = std::cos(lean) * t.t + sign * std::sin(lean) * t.edge;
                if (torchHit(*this, body, t.p, leaned, offcut)) continue;
                (sign > 0 ? pos : neg)[k] = lean;
                prefer = sign;
                found = any = true;
                break;
            }
            if (found) break;
        }
    }
    if (!any) return;
    // Ramp in and out: the lean changes by at most reorient_deg_s * dt per sample.
    const double rate = deg2rad(spec_.reorient_deg_s) * dt;
    for (auto* v : {&pos, &neg}) {
        for (size_t k = 1; k < n; ++k)
            (*v)[k] = std::max((*v)[k], (*v)[k - 1] - rate);
        for (size_t k = n - 1; k-- > 0;)
            (*v)[k] = std::max((*v)[k], (*v)[k + 1] - rate);
    }
    for (size_t k = 0; k < n; ++k) {
        TorchTarget& t = pass.samples[k];
        const Vec3 normal = t.t;
        t.lean_rad = pos[k] >= neg[k] ? pos[k] : -neg[k];
        t.t = std::cos(t.lean_rad) * normal + std::sin(t.lean_rad) * t.edge;
        if (!torchHit(*this, body, t.p, t.t, offcut)) continue;
        // Where the ramps of both directions meet: the nearest clear lean.
        for (double d = step; d <= 2 * maxLean; d += step) {
            bool found = false;
            for (double lean : {t.lean_rad + d, t.lean_rad - d}) {
                if (std::fabs(lean) > maxLean + 1e-12) continue;
                const Vec3 leaned = std::cos(lean) * normal + std::sin(lean) * t.edge;
                if (torchHit(*this, body, t.p, leaned, offcut)) continue;
                t.lean_rad = lean;
                t.t = leaned;
                found = true;
                break;
            }
            if (found) break;
        }
    }
}

std::vector<CutPass> EndCut::passes(double dt) const {
    // Travel and turn primitives along the outline.
    std::vector<Primitive> prims;
    const auto& segs = outline_.segments();
    const double v = spec_.speed_mm_s, w = deg2rad(spec_.reorient_deg_s);
    for (size_t i = 0; i < segs.size(); ++i) {
        const double s0 = outline_.segmentStart(i);
        // On a radius tighter than v / w (toe radii, small root fillets) the torch would turn
        // at v / r, faster than it may (an L 50x50x5's 3.5 mm toe at 8 mm/s: 131 deg/s): the tip
        // slows there so that the torch turns at reorient_deg_s, as it does at a sharp toe.
        const double turn = segs[i].arc ? std::fabs(segs[i].a1 - segs[i].a0) : 0;
        if (segs[i].length > 0)
            prims.push_back(
                travelOf(s0, s0 + segs[i].length, std::max(segs[i].length, turn / w * v), i));
        if (i + 1 < segs.size()) {
            const double a0 = angleOf(segs[i].n1);
            const double da = std::remainder(angleOf(segs[i + 1].n0) - a0, 2 * kPi);
            if (std::fabs(da) > 1e-9)
                prims.push_back(turnOf(s0 + segs[i].length, a0, da, std::fabs(da) / w * v));
        }
    }
    // The target at fraction f of a stretch.
    auto pointOf = [&](const Primitive& p, double f, bool groovePass) {
        if (!p.turn) {
            const double s = p.s0 + f * (p.s1 - p.s0);
            // On its own face: a sample at the face's end must not take the next face's
            // normal (the torch would turn a whole corner in one step).
            return target(outline_.onSegment(p.segment, s), s, groovePass);
        }
        OutlinePoint o = outline_.at(p.s0);
        const double a = p.a0 + f * p.da;
        o.normal = Vec2(std::cos(a), std::sin(a));
        o.tangent = Vec2(-o.normal.y(), o.normal.x());
        TorchTarget t = target(o, p.s0, false);
        t.turning = true;
        return t;
    };
    // The time law of a stretch on the world path: the tip moves at v along its points (the
    // outline in the mitred plane is longer than the square outline: 1 / cos of the mitre
    // across the cut line, the bevel's offset where the tilt ramps), or slower where the
    // untilted torch would turn faster than w (a torch turn, a tight radius); a turn at a
    // corner, measured in the cut plane, is a turn by another angle than the outline's.
    auto timeLaw = [&](Primitive& p, bool groovePass) {
        const bool arc = !p.turn && segs[p.segment].arc;
        if (!groovePass && !p.turn && !arc) {
            // A face of the plain cut: a straight line in the cut plane, its length scaled
            // uniformly (exactly 1 for a square cut).
            const Vec2 d = (segs[p.segment].p1 - segs[p.segment].p0).normalized();
            const double rise = d.x() * tanV_ + d.y() * tanH_;
            const double scale = std::sqrt(1 + rise * rise);
            p.length = (p.s1 - p.s0) * scale;
            p.effective *= scale;
            return;
        }
        if (!groovePass && square_) { // the outline itself: the law set up with the stretch
            p.length = p.turn ? 0 : p.s1 - p.s0;
            return;
        }
        // Nodes every 0.05 mm or 0.5 deg of the stretch (at least 64).
        const double nodes = p.turn ? rad2deg(std::fabs(p.da)) / 0.5 : (p.s1 - p.s0) / 0.05;
        const size_t n = static_cast<size_t>(std::clamp(std::ceil(nodes), 64.0, 2e4));
        p.table.assign(n + 1, 0.0);
        p.length = 0;
        TorchTarget prev = pointOf(p, 0, groovePass);
        for (size_t i = 1; i <= n; ++i) {
            const TorchTarget t =
                pointOf(p, static_cast<double>(i) / static_cast<double>(n), groovePass);
            const double moved = p.turn ? 0 : (t.p - prev.p).norm();
            const double turned = std::atan2(prev.t0.cross(t.t0).norm(), prev.t0.dot(t.t0));
            p.length += moved;
            p.table[i] = p.table[i - 1] + std::max(moved, turned / w * v);
            prev = t;
        }
        p.effective = p.table.back();
    };
    std::vector<CutPass> out;
    auto makePass = [&](const std::string& name, bool grooveArm, bool groovePass,
                        std::vector<Primitive> ps) {
        double total = 0;
        CutPass pass;
        pass.name = name;
        pass.groove_arm = grooveArm;
        for (auto& p : ps) {
            timeLaw(p, groovePass);
            total += p.effective;
            pass.length_mm += p.length;
        }
        const SpeedProfile profile(total, v, spec_.ramp_s);
        pass.duration_s = profile.duration();
        const size_t n = static_cast<size_t>(std::floor(profile.duration() / dt)) + 1;
        size_t pi = 0;
        double primStart = 0;
        for (size_t k = 0; k <= n; ++k) {
            const double dist =
                profile.distance(std::min(static_cast<double>(k) * dt, profile.duration()));
            while (pi + 1 < ps.size() && dist > primStart + ps[pi].effective) {
                primStart += ps[pi].effective;
                ++pi;
            }
            pass.samples.push_back(
                pointOf(ps[pi], fractionAt(ps[pi], dist - primStart), groovePass));
        }
        applyLean(pass, dt);
        out.push_back(std::move(pass));
    };
    // The path arm, in the (mitre) cut plane; turned over (setup 2) the end is already cut.
    if (!turnedOver()) makePass("square", false, false, prims);
    // The groove arm bevels face by face (its torch cannot turn round the toes: turning the
    // torch in the cut plane swings its whole 2R arm); a joint move links the faces. A pass
    // starts and ends where the blend has reached kMinBevelDeg: below it the bevel lies within
    // the square kerf (D tan 3 deg = 1 mm at D = 20 mm), and at tilt 0 the groove arm, its base
    // plane in the square cut plane, is singular (joints 4, 5 parallel to 1, 2).
    constexpr double kMinBevelDeg = 3;
    for (size_t i = 0; i < segs.size(); ++i) {
        const GrooveSpec* gs = grooveOf(i);
        if (!gs || segs[i].length <= 0) continue;
        const double s0 = outline_.segmentStart(i);
        const double trim =
            std::min(spec_.blend_mm * std::min(1.0, kMinBevelDeg / std::max(1e-9, gs->angle_deg)),
                     segs[i].length / 4);
        makePass("groove " + segs[i].name + (turnedOver() ? " (setup 2, turned over)" : ""), true,
                 true,
                 {travelOf(s0 + trim, s0 + segs[i].length - trim, segs[i].length - 2 * trim, i)});
    }
    return out;
}

std::string setupTwoProblem(const SectionSteelSpec& spec) {
    if (spec.cut.setup != 2 || EndCut(spec).hasGroove()) return {};
    const std::string underside = spec.section.family == SectionFamily::L
                                      ? messageC("horizontal leg")
                                      : messageC("bottom flange");
    return messageC("end_cut.setup = 2 (the section turned over): nothing is left to cut - "
                    "setup 2 cuts only the bevel on the underside of the %s (on the conveyor in "
                    "setup 1) that a K groove on the flanges needs, and end_cut.flanges.groove = "
                    "\"%s\"; plan setup 1 (end_cut.setup = 1)",
                    underside.c_str(), toString(spec.cut.flanges.type));
}

} // namespace cutcell::section_steel
