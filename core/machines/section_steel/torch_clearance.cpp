#include "core/machines/section_steel/torch_clearance.h"

#include "core/machines/section_steel/end_cut_path.h"

#include <algorithm>
#include <cmath>

namespace cutcell::section_steel {

std::optional<TorchHit> torchHit(const EndCut& cut, const TorchBody& body, const Vec3& tip,
                                 const Vec3& torch, bool offcutPresent) {
    const SectionOutline& o = cut.outline();
    const Vec3 m = cut.planeNormal();
    constexpr double kNozzleCone = 0.3; // radius growth per mm behind the tip
    const SectionDims& dims = o.dims();
    const double yLo = -dims.b_mm / 2, yHi = dims.b_mm / 2, zHi = dims.h_mm; // bounding box
    for (double b = 3; b <= body.length_mm + 1e-9; b += 2) {
        const Vec3 q = tip - b * torch;
        const double radius = std::min(body.radius_mm, kNozzleCone * b);
        // Signed distance from the cut plane, positive on the kept side.
        const double kept = (cut.planeX(q.y(), q.z()) - q.x()) * m.x();
        if (!offcutPresent && kept < -radius) continue; // past the cut: nothing there
        // Outside the section's bounding box by more than the radius: clear (quick test).
        const double by = std::max({yLo - q.y(), q.y() - yHi, 0.0});
        const double bz = std::max({-q.z(), q.z() - zHi, 0.0});
        if (by * by + bz * bz >= radius * radius) continue;
        const double d = o.distanceToMaterial({q.y(), q.z()});
        // Beside the kept part's end face the nearest material may be the face itself.
        const double reach =
            offcutPresent || kept > 0 ? d : std::hypot(d, kept); // d = 0 inside the outline
        if (reach < radius) return TorchHit{b, q};
    }
    return std::nullopt;
}

} // namespace cutcell::section_steel
