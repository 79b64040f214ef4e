#include "core/machines/pipe_robot/robot_lead.h"

#include "core/common/c_format.h"
#include "core/machine/pipe_joint_section.h"
#include "core/process/lead_request.h"

#include <algorithm>
#include <cmath>

namespace cutcell {
namespace {

// Samples of a lead checked against the edge (a quarter arc's chord misses it by r (1 - cos
// (pi / 128)) = 3e-4 r: 0.002 mm on a 5 mm lead).
constexpr int kLeadSamples = 64;
// A lead point closer than half the kerf minus this to the edge (or this far on the part's side)
// would mark the part: the edge polyline's chords (0.2 mm) miss the curve by far less, and the
// samples of a lead are checked against half of it.
constexpr double kClearanceTolMm = 0.01;
// Central difference step of the torch path's direction (mm of arc length).
constexpr double kTangentStepMm = 1e-3;

double wrapPi(double a) {
    return a - 2 * kPi * std::round(a / (2 * kPi));
}

} // namespace

const char* toString(PathPart p) {
    switch (p) {
    case PathPart::Cut:
        return "cut";
    case PathPart::Descent:
        return "descent";
    case PathPart::LeadIn:
        return "lead-in";
    case PathPart::Overlap:
        return "overlap";
    case PathPart::LeadOut:
        return "lead-out";
    }
    return "?";
}

RobotLeadSettings robotLeadSettings(const Job& job) {
    RobotLeadSettings out;
    const LeadRequest r = requestLeads(job.process, cutPartWallMm(job));
    out.in = r.in;
    out.out = r.out;
    out.used = r.used;
    if (!out.used) return out;
    const ProcessSettings& s = r.settings;
    // The chart refused: nothing more. The heights are asked only for a lead (leadHeightKey),
    // so the problem below is the chart's for an overlap alone.
    if (!s.ok()) {
        out.problem = r.problem;
        out.problem_key = r.problem_key;
        return out;
    }
    out.pierce_delay_s = s.effective.get(CutFigure::PierceDelayS).value_or(0.0);
    out.pierce = out.in.used() || out.out.used();
    if (!out.pierce) return out; // an overlap alone: the cut runs on, pierced as before
    if (!r.problem.empty()) {
        out.problem = r.problem;
        out.problem_key = r.problem_key;
        return out;
    }
    out.pierce_height_mm = *s.effective.get(CutFigure::PierceHeightMm);
    out.cut_height_mm = *s.effective.get(CutFigure::CutHeightMm);
    if (out.pierce_height_mm < out.cut_height_mm) {
        out.problem = messageC("pierce height %.6g mm is below the cut height %.6g mm: the torch "
                               "pierces above the cut height, then comes down to it; set "
                               "process.override.pierce_height_mm to at least %.6g mm",
                               out.pierce_height_mm, out.cut_height_mm, out.cut_height_mm);
        out.problem_key = "process.override.pierce_height_mm";
    }
    return out;
}

void checkRobotLeads(IssueChecker& c, const Job& job) {
    const RobotLeadSettings s = robotLeadSettings(job);
    // The chart and the heights' presence are checkProcess's issues; their order is the robot's.
    if (s.pierce && !s.problem.empty() && s.pierce_height_mm < s.cut_height_mm)
        c.add(s.problem_key, s.problem);
}

RobotLeadPath::D RobotLeadPath::developed(const Vec3& p) const {
    const double phi = std::atan2(p.y(), p.x());
    return {p.z(), R_ * (phi0_ + wrapPi(phi - phi0_))};
}

Vec3 RobotLeadPath::work(D d) const {
    const double phi = d.u / R_;
    return {R_ * std::cos(phi), R_ * std::sin(phi), d.z};
}

CutPoint RobotLeadPath::torchAt(double s) const {
    const double L = cut_mm_;
    double w = s;
    if (w < 0 || w > L) w = std::fmod(std::fmod(s, L) + L, L);
    CutPoint c = geo_->atArcLength(w);
    if (kerf_mm_ > 0) offsetCutPoint(kerf_, c, kerf_mm_);
    return c;
}

RobotLeadPath::D RobotLeadPath::tangentAt(double s) const {
    const D a = developed(torchAt(s - kTangentStepMm).p_work);
    D b = developed(torchAt(s + kTangentStepMm).p_work);
    b.u = a.u + R_ * wrapPi((b.u - a.u) / R_); // across phi0 + pi
    const double dz = b.z - a.z, du = b.u - a.u, n = std::hypot(dz, du);
    return {dz / n, du / n};
}

// Left of the travel seen from outside the pipe is outward x tangent: for t = a e_z + b e_phi
// that is b e_z - a e_phi, i.e. (t.u, -t.z) developed; the kerf spec says which side is scrap.
RobotLeadPath::D RobotLeadPath::scrapNormal(D t) const {
    const double s = kerf_.scrap == ScrapSide::Left ? 1.0 : -1.0;
    return {s * t.u, -s * t.z};
}

// The lead-in at sigma (0 = the pierce point, L = the cut's start).
RobotLeadPath::D RobotLeadPath::leadInAt(double sigma, double L, D* tangent) const {
    const LeadKind kind = settings_.in.kind;
    if (kind == LeadKind::Line) {
        if (tangent) *tangent = {-n0_.z, -n0_.u};
        return {p0_.z + (L - sigma) * n0_.z, p0_.u + (L - sigma) * n0_.u};
    }
    const double r = 2 * L / kPi, th = -kPi / 2 + sigma / r;
    const double a = r * (1 - std::cos(th)), b = r * std::sin(th);
    if (tangent)
        *tangent = {std::sin(th) * n0_.z + std::cos(th) * t0_.z,
                    std::sin(th) * n0_.u + std::cos(th) * t0_.u};
    return {p0_.z + a * n0_.z + b * t0_.z, p0_.u + a * n0_.u + b * t0_.u};
}

// The lead-out at sigma (0 = where it leaves the cut, L = its end).
RobotLeadPath::D RobotLeadPath::leadOutAt(double sigma, double L, D* tangent) const {
    const LeadKind kind = settings_.out.kind;
    if (kind == LeadKind::Line) {
        if (tangent) *tangent = ne_;
        return {e_.z + sigma * ne_.z, e_.u + sigma * ne_.u};
    }
    const double r = 2 * L / kPi, th = sigma / r;
    const double a = r * (1 - std::cos(th)), b = r * std::sin(th);
    if (tangent)
        *tangent = {std::sin(th) * ne_.z + std::cos(th) * te_.z,
                    std::sin(th) * ne_.u + std::cos(th) * te_.u};
    return {e_.z + a * ne_.z + b * te_.z, e_.u + a * ne_.u + b * te_.u};
}

CutPoint RobotLeadPath::surfacePoint(D d, D tangent, const CutPoint& like, double s,
                                     const Vec3& axis) const {
    CutPoint c = like;
    // The joint's axis carried round the pipe axis to the point: the same in the surface's frame.
    const double turn = d.u / R_ - std::atan2(like.p_work.y(), like.p_work.x());
    const double ct = std::cos(turn), st = std::sin(turn);
    c.s_mm = s;
    c.p_work = work(d);
    c.p_main = kerf_.main_from_work * c.p_work;
    const double phi = d.u / R_;
    const Vec3 ePhi(-std::sin(phi), std::cos(phi), 0);
    c.normal_work = Vec3(-std::cos(phi), -std::sin(phi), 0);
    c.tangent_work = (tangent.z * Vec3::UnitZ() + tangent.u * ePhi).normalized();
    c.approach_work = Vec3(ct * axis.x() - st * axis.y(), st * axis.x() + ct * axis.y(), axis.z());
    return c;
}

bool RobotLeadPath::scrapDev(D d) const {
    // Crossings of the ray from the point toward +z with the edge: the hole's inside (odd); on
    // the branch end (the edge a graph round the pipe) the edge above the point (odd) or not.
    const double period = 2 * kPi * R_;
    int crossings = 0;
    for (size_t i = 0; i + 1 < edge_.size(); ++i) {
        const D p = edge_[i], q = edge_[i + 1];
        double u = d.u;
        if (wraps_) u += period * std::round((p.u - u) / period);
        if ((p.u <= u) == (q.u <= u)) continue;
        const double t = (u - p.u) / (q.u - p.u);
        if (p.z + t * (q.z - p.z) > d.z) ++crossings;
    }
    if (!wraps_) return crossings % 2 == 1;
    return scrapUp_ ? crossings % 2 == 0 : crossings % 2 == 1;
}

double RobotLeadPath::distanceDev(D d) const {
    const double period = 2 * kPi * R_;
    double best = 1e300;
    for (size_t i = 0; i + 1 < edge_.size(); ++i) {
        const D p = edge_[i], q = edge_[i + 1];
        double u = d.u;
        if (wraps_) u += period * std::round((p.u - u) / period);
        const double ux = q.z - p.z, uy = q.u - p.u, vx = d.z - p.z, vy = u - p.u;
        const double len2 = ux * ux + uy * uy;
        const double t = len2 > 0 ? std::clamp((vx * ux + vy * uy) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(vx - t * ux, vy - t * uy));
    }
    return best;
}

bool RobotLeadPath::onScrapSide(const Vec3& p_work) const {
    return scrapDev(developed(p_work));
}

double RobotLeadPath::distanceToEdge(const Vec3& p_work) const {
    return distanceDev(developed(p_work));
}

bool RobotLeadPath::clear(const std::vector<D>& pts) const {
    for (const D& d : pts) {
        const double dist = distanceDev(d);
        // Half the tolerance: the points between the samples keep the other half.
        if (dist < kerf_mm_ / 2 - kClearanceTolMm / 2) return false;
        if (!scrapDev(d) && dist > kClearanceTolMm) return false;
    }
    return true;
}

namespace {

// The longest length <= L whose lead is clear, to 1 um and rounded down (the figure the message
// shows is accepted as it is shown): bisection, a shorter lead stays nearer the joint.
template <class Clear> double longestClear(double L, Clear isClear) {
    double lo = 0, hi = L;
    for (int k = 0; k < 40; ++k) {
        const double mid = (lo + hi) / 2;
        (isClear(mid) ? lo : hi) = mid;
    }
    return std::floor(lo * 1000) / 1000;
}

} // namespace

RobotLeadPath::RobotLeadPath(const Job& job, const CutGeometry& geo, const KerfPathSpec& kerf,
                             double kerf_mm)
    : geo_(&geo), kerf_(kerf), kerf_mm_(kerf_mm), settings_(robotLeadSettings(job)) {
    cut_mm_ = geo.length();
    R_ = kerf.work_radius_mm;
    if (!settings_.used) return;
    if (!settings_.problem.empty()) {
        problem_ = settings_.problem;
        problemKey_ = settings_.problem_key;
        return;
    }
    start_ = torchAt(0);
    phi0_ = std::atan2(start_.p_work.y(), start_.p_work.x());
    descent_mm_ = settings_.pierce_height_mm - settings_.cut_height_mm;
    overlap_mm_ = settings_.out.overlap_mm;

    // The part's edge, developed and unwrapped along the curve.
    const double spacing = std::min(0.2, cut_mm_ / 2000);
    for (const CutPoint& c : geo.sampleEqualArcLength(spacing)) {
        D d = developed(c.p_work);
        if (!edge_.empty()) d.u = edge_.back().u + R_ * wrapPi((d.u - edge_.back().u) / R_);
        edge_.push_back(d);
    }
    const double turn = edge_.back().u - edge_.front().u;
    wraps_ = std::fabs(turn) > kPi * R_;
    // Left of a segment is (du, -dz): summed over a turn its z part is the turn's u.
    scrapUp_ = (kerf_.scrap == ScrapSide::Left ? 1.0 : -1.0) * turn > 0;

    p0_ = developed(start_.p_work);
    t0_ = tangentAt(0);
    n0_ = scrapNormal(t0_);
    leave_ = torchAt(overlap_mm_);
    e_ = developed(leave_.p_work);
    te_ = tangentAt(overlap_mm_);
    ne_ = scrapNormal(te_);

    auto tooLong = [&](const char* which, const char* what, double L, double limit) {
        problem_ = messageC("process.%s.length_mm = %.6g mm is too long for the %s: the %s would "
                            "reach the part's edge [it must stay half the kerf, %.6g mm, off it "
                            "on the scrap side]; the longest that fits is %.3f mm",
                            which, L, job.cut.target == CutTarget::Main ? "hole" : "branch end",
                            what, kerf_mm_ / 2, limit);
        problemKey_ = std::string("process.") + which + ".length_mm";
    };
    if (settings_.in.used()) {
        auto samples = [&](double L) {
            std::vector<D> pts;
            for (int i = 0; i < kLeadSamples; ++i) // the joint (sigma = L) is the cut's
                pts.push_back(leadInAt(L * i / kLeadSamples, L, nullptr));
            return pts;
        };
        const double L = settings_.in.length_mm;
        if (!clear(samples(L))) {
            tooLong("lead_in", "lead-in", L,
                    longestClear(L, [&](double l) { return clear(samples(l)); }));
            return;
        }
        lead_in_mm_ = L;
    }
    if (settings_.out.used()) {
        auto samples = [&](double L) {
            std::vector<D> pts;
            for (int i = 1; i <= kLeadSamples; ++i)
                pts.push_back(leadOutAt(L * i / kLeadSamples, L, nullptr));
            return pts;
        };
        const double L = settings_.out.length_mm;
        if (!clear(samples(L))) {
            tooLong("lead_out", "lead-out", L,
                    longestClear(L, [&](double l) { return clear(samples(l)); }));
            lead_in_mm_ = 0;
            return;
        }
        lead_out_mm_ = L;
    }
}

CutPoint RobotLeadPath::descentAt(double d) const {
    // Above the pierce point (the lead-in's first point, else the cut's start) along the axis.
    CutPoint c = lead_in_mm_ > 0 ? travelAt(0) : start_;
    const Vec3 a = c.approach_work;
    c.p_work -= (descent_mm_ - d) * a;
    c.p_main = kerf_.main_from_work * c.p_work;
    c.tangent_work = a;
    return c;
}

CutPoint RobotLeadPath::travelAt(double d, PathPart* part) const {
    const double in = lead_in_mm_, L = cut_mm_, o = overlap_mm_;
    D t{};
    if (d < in) {
        if (part) *part = PathPart::LeadIn;
        const D p = leadInAt(d, in, &t);
        return surfacePoint(p, t, start_, d - in, start_.approach_work);
    }
    if (d <= in + L) {
        if (part) *part = PathPart::Cut;
        CutPoint c = torchAt(d - in);
        c.s_mm = d - in;
        return c;
    }
    if (d <= in + L + o) {
        if (part) *part = PathPart::Overlap;
        CutPoint c = torchAt(d - in - L);
        c.s_mm = d - in;
        return c;
    }
    if (part) *part = PathPart::LeadOut;
    const double sigma = std::min(d - in - L - o, lead_out_mm_);
    const D p = leadOutAt(sigma, lead_out_mm_, &t);
    return surfacePoint(p, t, leave_, L + o + sigma, leave_.approach_work);
}

} // namespace cutcell
