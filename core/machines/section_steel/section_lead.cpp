#include "core/machines/section_steel/section_lead.h"

#include "core/common/c_format.h"
#include "core/machines/section_steel/section_kerf.h"
#include "core/process/process_spec.h"
#include "core/trajectory/speed_profile.h"

#include <algorithm>
#include <cmath>

namespace cutcell::section_steel {
namespace {

// The point at arc length s (0 .. L) of a lead-in ending at p0 (in: from its first point) or a
// lead-out leaving p0 (out: from p0), in the plane spanned by the travel e and the direction
// away from the material a.
Vec3 leadAt(const Vec3& p0, const Vec3& e, const Vec3& a, LeadKind kind, double L, double s,
            bool in) {
    if (kind == LeadKind::Line) return in ? Vec3(p0 - (L - s) * e) : Vec3(p0 + s * e);
    const double r = 2 * L / kPi;
    const double th = in ? -kPi / 2 + s / r : s / r; // -pi/2 .. 0 (in), 0 .. pi/2 (out)
    return p0 + (r * (1 - std::cos(th))) * a + (r * std::sin(th)) * e;
}

// Samples of a stretch of length `length` (tool points by arc length), dt apart from rest to
// rest at `speed` with `ramp` s ramps: from its start (includeStart) to its end (includeEnd).
template <class At>
void sampleStretch(std::vector<TorchTarget>& out, const TorchTarget& like, int role,
                   const Vec3& kerfShift, double length, double speed, double ramp, double dt,
                   bool includeStart, bool includeEnd, At at, double* duration) {
    const SpeedProfile profile(length, speed, ramp);
    const size_t n = static_cast<size_t>(std::floor(profile.duration() / dt)) + 1;
    for (size_t k = includeStart ? 0 : 1; k <= (includeEnd ? n : n - 1); ++k) {
        TorchTarget t = like;
        t.p = at(profile.distance(std::min(static_cast<double>(k) * dt, profile.duration())));
        t.edge_p = t.p - kerfShift;
        t.turning = false;
        t.lead = role;
        out.push_back(t);
    }
    *duration += static_cast<double>(n) * dt;
}

} // namespace

SteelLeadRequest steelLeadRequest(const Job& job) {
    SteelLeadRequest r;
    const ProcessSpec& p = job.process;
    if (!p.used) return r;
    const SectionSteelSpec* spec = job.machine_spec.as<SectionSteelSpec>();
    if (!spec) return r;
    if (p.lead_out.overlap_mm > 0) {
        r.problem_key = "process.lead_out.overlap_mm";
        r.problem = messageC(
            "process.lead_out.overlap_mm = %.6g mm: the section-steel cutter's cut is open (it "
            "starts and ends at the free edges beside the face on the conveyor): there is no "
            "start to overlap; remove it",
            p.lead_out.overlap_mm);
        return r;
    }
    if (!p.lead_in.used() && !p.lead_out.used()) return r;
    if (spec->cut.setup == 2) {
        const bool in = p.lead_in.used();
        r.problem_key = in ? "process.lead_in.kind" : "process.lead_out.kind";
        r.problem =
            messageC("process.%s.kind = \"%s\": setup 2 (end_cut.setup = 2) cuts only "
                     "bevels, which start and end off the material and take no lead; "
                     "set \"none\" or remove it",
                     in ? "lead_in" : "lead_out", toString(in ? p.lead_in.kind : p.lead_out.kind));
        return r;
    }
    const ProcessSettings s = resolveProcess(p, steelPartThicknessMm(*spec));
    if (!s.ok()) {
        r.problem = s.outcome.message;
        r.problem_key = s.outcome.key;
        return r;
    }
    if (const std::string why = leadHeightProblem(p, s); !why.empty()) {
        r.problem = why;
        r.problem_key = leadHeightKey(p, s);
        return r;
    }
    r.spec.in = p.lead_in;
    r.spec.out = p.lead_out;
    r.spec.pierce_height_mm = *s.effective.get(CutFigure::PierceHeightMm);
    r.spec.cut_height_mm = *s.effective.get(CutFigure::CutHeightMm);
    return r;
}

Vec3 steelCutTangent(const TorchTarget& t) {
    return t.edge.normalized();
}

Vec3 steelAwayFromMaterial(const TorchTarget& t) {
    return -t.t0.normalized();
}

std::vector<Vec3> steelLeadInPoints(const TorchTarget& start, LeadKind kind, double length_mm) {
    std::vector<Vec3> out;
    if (kind == LeadKind::None) return out;
    const Vec3 e = steelCutTangent(start), a = steelAwayFromMaterial(start);
    const int n = kind == LeadKind::Line ? 1 : kLeadArcSegments;
    for (int k = 0; k < n; ++k)
        out.push_back(leadAt(start.p, e, a, kind, length_mm, length_mm * k / n, true));
    return out;
}

std::vector<Vec3> steelLeadOutPoints(const TorchTarget& end, LeadKind kind, double length_mm) {
    std::vector<Vec3> out;
    if (kind == LeadKind::None) return out;
    const Vec3 e = steelCutTangent(end), a = steelAwayFromMaterial(end);
    const int n = kind == LeadKind::Line ? 1 : kLeadArcSegments;
    for (int k = 1; k <= n; ++k)
        out.push_back(leadAt(end.p, e, a, kind, length_mm, length_mm * k / n, false));
    return out;
}

SteelLeadSamples steelLeadSamples(const SectionSteelSpec& spec, const CutPass& square,
                                  const SteelLeadSpec& leads, double dt) {
    SteelLeadSamples out;
    if (square.samples.empty() || !leads.used()) return out;
    const double v = spec.speed_mm_s, ramp = spec.ramp_s;
    const TorchTarget& first = square.samples.front();
    const TorchTarget& last = square.samples.back();
    const Vec3 shiftIn = first.p - first.edge_p, shiftOut = last.p - last.edge_p;
    if (leads.in.used()) {
        const Vec3 e = steelCutTangent(first), a = steelAwayFromMaterial(first);
        const double L = leads.in.length_mm;
        out.pierce_point = leadAt(first.p, e, a, leads.in.kind, L, 0, true);
        out.lead_in_mm = L;
    } else {
        out.pierce_point = first.p; // a lead-out only: fired over the cut's start
    }
    // The torch axis: the tool point (pierce - cut height) back along it, the nozzle the pierce
    // height above the surface.
    const Vec3 axis = first.t.normalized();
    const double up = leads.pierce_height_mm - leads.cut_height_mm;
    out.pierce_nozzle = out.pierce_point - leads.pierce_height_mm * axis;
    const Vec3 fired = out.pierce_point - up * axis;
    const bool leadIn = leads.in.used();
    sampleStretch(
        out.before, first, kLeadPierce, shiftIn, std::fabs(up), v, ramp, dt, true, !leadIn,
        [&](double s) { return Vec3(fired + (up >= 0 ? s : -s) * axis); }, &out.before_s);
    if (leadIn) {
        const Vec3 e = steelCutTangent(first), a = steelAwayFromMaterial(first);
        sampleStretch(
            out.before, first, kLeadIn, shiftIn, leads.in.length_mm, v, ramp, dt, true, false,
            [&](double s) {
                return leadAt(first.p, e, a, leads.in.kind, leads.in.length_mm, s, true);
            },
            &out.before_s);
    } else {
        // Without a lead-in the torch comes down onto the cut's start: the last sample of the
        // pierce stretch is the start itself, which the pass gives.
        if (!out.before.empty()) out.before.pop_back();
    }
    if (leads.out.used()) {
        const Vec3 e = steelCutTangent(last), a = steelAwayFromMaterial(last);
        sampleStretch(
            out.after, last, kLeadOut, shiftOut, leads.out.length_mm, v, ramp, dt, false, true,
            [&](double s) {
                return leadAt(last.p, e, a, leads.out.kind, leads.out.length_mm, s, false);
            },
            &out.after_s);
        out.lead_out_mm = leads.out.length_mm;
    }
    out.before_s = dt * static_cast<double>(out.before.size());
    out.after_s = dt * static_cast<double>(out.after.size());
    return out;
}

void addSteelLeads(CutPass& square, const SteelLeadSamples& leads) {
    std::vector<TorchTarget> all = leads.before;
    all.insert(all.end(), square.samples.begin(), square.samples.end());
    all.insert(all.end(), leads.after.begin(), leads.after.end());
    square.samples = std::move(all);
    square.duration_s += leads.before_s + leads.after_s;
}

} // namespace cutcell::section_steel
