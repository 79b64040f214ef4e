#include "core/machines/section_steel/section_kerf.h"

#include "core/common/c_format.h"
#include "core/process/kerf_offset.h"
#include "core/process/process_spec.h"

#include <algorithm>
#include <cmath>

namespace cutcell::section_steel {
namespace {

// Where a target is, for messages: "pass groove top flange, upper face (top flange, upper face,
// s = 120.0 mm)".
std::string where(const EndCut& cut, const CutPass& pass, const TorchTarget& t) {
    const char* segment = cut.outline().segments()[t.segment].name.c_str();
    if (t.turning)
        return messageC("pass %s (%s, s = %.1f mm, turning at the corner)", pass.name.c_str(),
                        segment, t.s_mm);
    return messageC("pass %s (%s, s = %.1f mm)", pass.name.c_str(), segment, t.s_mm);
}

// The groove's key of a bevelled face (grooveOf() maps flanges and legs' horizontal faces to
// end_cut.flanges, webs and vertical legs to end_cut.web).
const char* grooveKey(const EndCut& cut, size_t segment) {
    return cut.outline().segments()[segment].kind == FaceKind::Web ? "end_cut.web"
                                                                   : "end_cut.flanges";
}

// Moves every target by sign k/2 across its cut surface (from edge_p when offsetting, from p
// going back).
Outcome shiftPasses(const EndCut& cut, std::vector<CutPass>& passes, double kerf_mm, bool toTorch) {
    const Vec3 m = cut.planeNormal();
    std::vector<CutPass> out = passes;
    for (CutPass& pass : out)
        for (TorchTarget& t : pass.samples) {
            const KerfPoint k =
                toTorch ? offsetOnPrism(t.edge_p, t.edge, t.t, Vec3::UnitX(), m, kerf_mm)
                        : edgeOnPrism(t.p, t.edge, t.t, Vec3::UnitX(), m, kerf_mm);
            if (!k.outcome.ok())
                return Outcome::refuse(
                    messageC("at %s: %s", where(cut, pass, t).c_str(), k.outcome.message.c_str()));
            t.p = k.point;
        }
    if (toTorch) {
        // The bevel's strip on the face: at the pass's full tilt the torch centre must stay on
        // the face, no further along the bar than the cut plane (the end the square pass left).
        for (const CutPass& pass : out) {
            if (!pass.groove_arm || pass.samples.empty()) continue;
            double full = 0;
            for (const TorchTarget& t : pass.samples)
                full = std::max(full, t.tilt_rad);
            for (const TorchTarget& t : pass.samples) {
                if (t.tilt_rad < full - 1e-12) continue;
                const double strip = cut.planeX(t.edge_p.y(), t.edge_p.z()) - t.edge_p.x();
                const double moved = t.p.x() - t.edge_p.x();
                if (moved <= strip) continue;
                // moved is linear in k: the widest kerf that keeps the torch on the face.
                const double limit = kerf_mm * strip / moved;
                const char* key = grooveKey(cut, t.segment);
                const GrooveSpec* g = cut.grooveOf(t.segment);
                return Outcome::refuse(messageC(
                    "the kerf %.6g mm is too wide for the %s bevel of %s (%s.angle_deg = %.6g "
                    "deg) at %s: the bevel takes a strip %.6g mm wide off the face (along the "
                    "bar), and the torch centre, k/2 across the bevel surface, would run %.6g mm "
                    "into it - beyond the bar's end; the kerf may be at most %.6g mm here "
                    "(k <= 2 x strip x cos of the bevel surface to the bar)",
                    kerf_mm, g ? toString(g->type) : "?", key, key, rad2deg(full),
                    where(cut, pass, t).c_str(), strip, moved, limit));
            }
        }
    }
    passes = std::move(out);
    return Outcome::done();
}

} // namespace

double steelPartThicknessMm(const SectionSteelSpec& spec) {
    return std::max(spec.section.tf_mm, spec.section.tw_mm);
}

double steelKerfMm(const Job& job) {
    if (!job.process.used) return 0;
    const SectionSteelSpec* spec = job.machine_spec.as<SectionSteelSpec>();
    if (!spec) return 0;
    const ProcessSettings s = resolveProcess(job.process, steelPartThicknessMm(*spec));
    return s.ok() ? s.kerfMm() : 0.0;
}

double squarePassShiftMm(const EndCut& cut, double kerf_mm) {
    return kerf_mm / 2 / cut.planeNormal().x();
}

Outcome compensateSteelKerf(const EndCut& cut, std::vector<CutPass>& passes, double kerf_mm) {
    if (kerf_mm == 0) return Outcome::done();
    return shiftPasses(cut, passes, kerf_mm, true);
}

Outcome steelEdgeFromTorch(const EndCut& cut, std::vector<CutPass>& torch, double kerf_mm) {
    if (kerf_mm == 0) return Outcome::done();
    return shiftPasses(cut, torch, kerf_mm, false);
}

} // namespace cutcell::section_steel
