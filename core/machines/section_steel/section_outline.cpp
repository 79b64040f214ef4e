#include "core/machines/section_steel/section_outline.h"

#include "core/common/c_format.h"
#include "core/common/types.h"
#include "core/job/section_reader.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cutcell::section_steel {
namespace {

struct Corner {
    Vec2 v;
    double r; // fillet radius at this corner (0 = sharp)
};
struct Edge {
    const char* name;
    FaceKind kind;
    double thickness;
    bool grooveSide;
    bool tableFace = false;
};

Vec2 outward(const Vec2& d) {
    return {d.y(), -d.x()}; // right of the direction: material is on the left
}

double angleOf(const Vec2& v) {
    return std::atan2(v.y(), v.x());
}

} // namespace

const char* toString(FaceKind k) {
    switch (k) {
    case FaceKind::Flange:
        return "flange";
    case FaceKind::Web:
        return "web";
    case FaceKind::Toe:
        return "toe";
    case FaceKind::Fillet:
        return "root fillet";
    case FaceKind::Leg:
        return "leg";
    }
    return "?";
}

SectionOutline::SectionOutline(const SectionDims& d, bool turnedOver)
    : dims_(d), turned_(turnedOver) {
    // A tapered (UPN) flange is drawn parallel at the thickness of the same area: t is given
    // at b/2 from the web's back, the outstand's mean thickness is at (b + tw)/2.
    const double h = d.h_mm, b = d.b_mm, tw = d.tw_mm, r = d.r_mm, r2 = d.r2_mm;
    const double tf = d.tf_mm - d.slope_pct / 100 * tw / 2;
    std::vector<Corner> c;
    std::vector<Edge> e; // e[i] runs from c[i] to c[i + 1] (the last one back to c[0])
    using K = FaceKind;
    switch (d.family) {
    case SectionFamily::I:
        c = {{{b / 2, 0}, 0},        {{b / 2, tf}, 0},   {{tw / 2, tf}, r}, {{tw / 2, h - tf}, r},
             {{b / 2, h - tf}, 0},   {{b / 2, h}, 0},    {{-b / 2, h}, 0},  {{-b / 2, h - tf}, 0},
             {{-tw / 2, h - tf}, r}, {{-tw / 2, tf}, r}, {{-b / 2, tf}, 0}, {{-b / 2, 0}, 0}};
        e = {{"bottom flange, toe +y", K::Toe, tf, false},
             {"bottom flange, upper face +y", K::Flange, tf, true},
             {"web, face +y", K::Web, tw, true},
             {"top flange, lower face +y", K::Flange, tf, false},
             {"top flange, toe +y", K::Toe, tf, false},
             {"top flange, upper face", K::Flange, tf, true},
             {"top flange, toe -y", K::Toe, tf, false},
             {"top flange, lower face -y", K::Flange, tf, false},
             {"web, face -y", K::Web, tw, false},
             {"bottom flange, upper face -y", K::Flange, tf, true},
             {"bottom flange, toe -y", K::Toe, tf, false},
             {"bottom flange, underside", K::Flange, tf, false, true}};
        break;
    case SectionFamily::U:
        c = {{{b / 2, 0}, 0},        {{b / 2, tf}, r2},
             {{-b / 2 + tw, tf}, r}, {{-b / 2 + tw, h - tf}, r},
             {{b / 2, h - tf}, r2},  {{b / 2, h}, 0},
             {{-b / 2, h}, 0},       {{-b / 2, 0}, 0}};
        e = {{"bottom flange, toe", K::Toe, tf, false},
             {"bottom flange, upper face", K::Flange, tf, true},
             {"web, inner face", K::Web, tw, true},
             {"top flange, lower face", K::Flange, tf, false},
             {"top flange, toe", K::Toe, tf, false},
             {"top flange, upper face", K::Flange, tf, true},
             {"web, outer face", K::Web, tw, false},
             {"bottom flange, underside", K::Flange, tf, false, true}};
        break;
    case SectionFamily::L:
        c = {{{b / 2, 0}, 0},        {{b / 2, tf}, r2}, {{-b / 2 + tw, tf}, r},
             {{-b / 2 + tw, h}, r2}, {{-b / 2, h}, 0},  {{-b / 2, 0}, 0}};
        e = {{"horizontal leg, toe", K::Toe, tf, false},
             {"horizontal leg, upper face", K::Flange, tf, true},
             {"vertical leg, inner face", K::Web, tw, true},
             {"vertical leg, toe", K::Toe, tw, false},
             {"vertical leg, outer face", K::Web, tw, false},
             {"horizontal leg, underside", K::Flange, tf, false, true}};
        break;
    }
    // c and e describe the closed loop: the last edge (the table face in setup 1) runs from
    // the last corner back to the first. Turned over, every corner goes to (-y, h - z) (a
    // rotation: the loop stays counter-clockwise) and the edge now lying on the table (at
    // z = 0: the top flange's / the vertical leg's upper end) leaves the chain, which starts
    // at its right end. The chain's last corner may keep a radius (an L's toe radius r2 at its
    // foot): the outline then ends with that arc, down to the table.
    Edge tableEdge = e.back();
    if (turnedOver) {
        for (Corner& k : c)
            k.v = Vec2(-k.v.x(), h - k.v.y());
        const size_t n = c.size();
        size_t table = n;
        for (size_t i = 0; i < n; ++i)
            if (std::fabs(c[i].v.y()) < 1e-12 && std::fabs(c[(i + 1) % n].v.y()) < 1e-12) table = i;
        if (table == n) throw std::logic_error("turned section outline: no face on the table");
        std::vector<Corner> c2;
        std::vector<Edge> e2;
        for (size_t k = 1; k <= n; ++k) {
            c2.push_back(c[(table + k) % n]);
            if (k < n) e2.push_back(e[(table + k) % n]);
        }
        tableEdge = e[table];
        c2.front().r = 0; // sharp in every family (the top flange's / the leg's outer corner)
        c = std::move(c2);
        e = std::move(e2);
    } else {
        e.pop_back(); // the table face
    }
    // Round the corners: every corner of these sections is 90 deg, so a fillet of radius r
    // touches both edges at r from the corner and has its centre at v - r d_in + r d_out.
    auto dir = [&](size_t i) { return Vec2((c[i + 1].v - c[i].v).normalized()); };
    for (size_t i = 0; i < e.size(); ++i) {
        const Vec2 along = dir(i);
        const double cutStart = c[i].r, cutEnd = c[i + 1].r;
        OutlineSegment s;
        s.name = e[i].name;
        s.kind = e[i].kind;
        s.thickness_mm = e[i].thickness;
        s.groove_side = e[i].grooveSide;
        s.former_table_face = e[i].tableFace;
        s.p0 = c[i].v + cutStart * along;
        s.p1 = c[i + 1].v - cutEnd * along;
        s.n0 = s.n1 = outward(along);
        s.length = (s.p1 - s.p0).norm();
        segments_.push_back(s);
        if (cutEnd > 0) {
            const bool last = i + 1 == e.size(); // the fillet runs down to the table face
            const Vec2 dOut = last ? Vec2((c.front().v - c.back().v).normalized()) : dir(i + 1);
            const Edge& next = last ? tableEdge : e[i + 1];
            OutlineSegment f;
            // Counter-clockwise: a left turn is a convex corner (toe radius), a right turn a
            // concave one (root fillet).
            const bool convex = along.x() * dOut.y() - along.y() * dOut.x() > 0;
            f.name = std::string(convex ? "toe radius (" : "root fillet (") + e[i].name + " / " +
                     next.name + ")";
            f.kind = FaceKind::Fillet;
            f.thickness_mm = std::min(e[i].thickness, next.thickness);
            f.arc = true;
            f.radius = cutEnd;
            f.centre = c[i + 1].v - cutEnd * along + cutEnd * dOut;
            f.p0 = s.p1;
            f.p1 = c[i + 1].v + cutEnd * dOut;
            f.a0 = angleOf(f.p0 - f.centre);
            double a1 = angleOf(f.p1 - f.centre);
            while (a1 - f.a0 > kPi)
                a1 -= 2 * kPi;
            while (a1 - f.a0 < -kPi)
                a1 += 2 * kPi;
            f.a1 = a1;
            f.n0 = outward(along);
            f.n1 = outward(dOut);
            f.length = cutEnd * std::fabs(f.a1 - f.a0);
            segments_.push_back(f);
        }
    }
    for (const auto& s : segments_) {
        starts_.push_back(length_);
        length_ += s.length;
    }
    // Closed polygon: the outline (arcs as 8 chords) and the table face back to the start.
    for (const auto& s : segments_) {
        if (!s.arc) {
            polygon_.push_back(s.p0);
            continue;
        }
        for (int k = 0; k < 8; ++k) {
            const double a = s.a0 + (s.a1 - s.a0) * k / 8.0;
            polygon_.push_back(s.centre + s.radius * Vec2(std::cos(a), std::sin(a)));
        }
    }
    polygon_.push_back(segments_.back().p1);
}

OutlinePoint SectionOutline::at(double s) const {
    s = std::clamp(s, 0.0, length_);
    size_t i =
        static_cast<size_t>(std::upper_bound(starts_.begin(), starts_.end(), s) - starts_.begin());
    i = i == 0 ? 0 : i - 1;
    while (i + 1 < segments_.size() && segments_[i].length == 0)
        ++i;
    return onSegment(i, s);
}

OutlinePoint SectionOutline::onSegment(size_t i, double s) const {
    const OutlineSegment& g = segments_[i];
    const double u = g.length > 0 ? std::clamp((s - starts_[i]) / g.length, 0.0, 1.0) : 0.0;
    OutlinePoint o;
    o.segment = i;
    if (!g.arc) {
        o.p = g.p0 + u * (g.p1 - g.p0);
        o.tangent = (g.p1 - g.p0).normalized();
        o.normal = g.n0;
    } else {
        const double a = g.a0 + u * (g.a1 - g.a0);
        const Vec2 radial(std::cos(a), std::sin(a));
        o.p = g.centre + g.radius * radial;
        const double sgn = g.a1 > g.a0 ? 1.0 : -1.0;
        o.tangent = sgn * Vec2(-radial.y(), radial.x());
        o.normal = {o.tangent.y(), -o.tangent.x()};
    }
    return o;
}

bool SectionOutline::contains(const Vec2& q) const {
    bool in = false;
    const size_t n = polygon_.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const Vec2& a = polygon_[i];
        const Vec2& b = polygon_[j];
        if ((a.y() > q.y()) != (b.y() > q.y()) &&
            q.x() < (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y()) + a.x())
            in = !in;
    }
    return in;
}

double SectionOutline::distanceToOutline(const Vec2& q) const {
    double best = 1e300;
    for (const auto& g : segments_) {
        double dist;
        if (!g.arc) {
            const Vec2 d = g.p1 - g.p0;
            const double L2 = d.squaredNorm();
            const double u = L2 > 0 ? std::clamp((q - g.p0).dot(d) / L2, 0.0, 1.0) : 0.0;
            dist = (q - (g.p0 + u * d)).norm();
        } else {
            const double a = angleOf(q - g.centre);
            double lo = std::min(g.a0, g.a1), hi = std::max(g.a0, g.a1);
            double aa = a;
            while (aa < lo)
                aa += 2 * kPi;
            dist = aa <= hi ? std::fabs((q - g.centre).norm() - g.radius)
                            : std::min((q - g.p0).norm(), (q - g.p1).norm());
        }
        best = std::min(best, dist);
    }
    return best;
}

double SectionOutline::area() const {
    // Green: A = 1/2 closed integral of (y dz - z dy) over the outline and the table face.
    double twice = 0;
    for (const auto& g : segments_) {
        if (!g.arc) {
            twice += g.p0.x() * g.p1.y() - g.p0.y() * g.p1.x();
            continue;
        }
        const double r = g.radius, cy = g.centre.x(), cz = g.centre.y();
        twice += r * r * (g.a1 - g.a0) + r * cy * (std::sin(g.a1) - std::sin(g.a0)) -
                 r * cz * (std::cos(g.a1) - std::cos(g.a0));
    }
    const Vec2 &a = segments_.back().p1, &b = segments_.front().p0; // the table face
    twice += a.x() * b.y() - a.y() * b.x();
    return twice / 2;
}

double SectionOutline::distanceToMaterial(const Vec2& q) const {
    if (contains(q)) return 0;
    double best = 1e300;
    const size_t n = polygon_.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const Vec2 e = polygon_[i] - polygon_[j];
        const double L2 = e.squaredNorm();
        const double u = L2 > 0 ? std::clamp((q - polygon_[j]).dot(e) / L2, 0.0, 1.0) : 0.0;
        best = std::min(best, (q - (polygon_[j] + u * e)).norm());
    }
    return best;
}

std::vector<std::pair<std::string, std::string>> checkSectionDims(const SectionDims& d,
                                                                  const std::string& k) {
    std::vector<std::pair<std::string, std::string>> out;
    auto range = [&](const char* f, double v, double lo, double hi) {
        if (!(v >= lo && v <= hi))
            out.push_back({k + "." + f, messageC("%s.%s = %.6g mm is outside [%.6g, %.6g] mm",
                                                 k.c_str(), f, v, lo, hi)});
    };
    range("h_mm", d.h_mm, 10, 1200);
    range("b_mm", d.b_mm, 10, 600);
    range("tw_mm", d.tw_mm, 1, 100);
    range("tf_mm", d.tf_mm, 1, 100);
    range("r_mm", d.r_mm, 0, 100);
    range("r2_mm", d.r2_mm, 0, 50);
    if (!out.empty()) return out;
    if (d.family != SectionFamily::I && d.r2_mm >= std::min(d.tw_mm, d.tf_mm))
        out.push_back({k + ".r2_mm",
                       messageC("%s.r2_mm = %.6g mm: the toe radius must be below the thickness "
                                "(%.6g mm)",
                                k.c_str(), d.r2_mm, std::min(d.tw_mm, d.tf_mm))});
    const bool isI = d.family == SectionFamily::I;
    const double webRoom = isI ? (d.b_mm - d.tw_mm) / 2 : d.b_mm - d.tw_mm;
    if (d.r_mm >= webRoom)
        out.push_back({k + ".r_mm", messageC("%s.r_mm = %.6g mm leaves no flat flange: it must be "
                                             "below %.6g mm (flange outstand)",
                                             k.c_str(), d.r_mm, webRoom)});
    const double clear = d.family == SectionFamily::L ? d.h_mm - d.tf_mm : d.h_mm - 2 * d.tf_mm;
    if (2 * d.r_mm >= clear && d.family != SectionFamily::L)
        out.push_back({k + ".r_mm", messageC("%s.r_mm = %.6g mm: two root radii do not fit "
                                             "between the flanges (%.6g mm)",
                                             k.c_str(), d.r_mm, clear)});
    if (d.r_mm >= clear && d.family == SectionFamily::L)
        out.push_back({k + ".r_mm", messageC("%s.r_mm = %.6g mm does not fit on the vertical leg "
                                             "(%.6g mm)",
                                             k.c_str(), d.r_mm, clear)});
    return out;
}

} // namespace cutcell::section_steel
