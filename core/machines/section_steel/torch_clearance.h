#pragma once
// The torch body against the section: a cylinder of radius `radius_mm` (a cone at the nozzle,
// radius growing at 0.3 mm per mm from the tip) along the torch axis, `length_mm` behind the
// tip. During the square pass the offcut is still there (material on both sides of the cut
// plane); during the bevel passes only the kept part is (material on the kept side).
#include "core/common/types.h"
#include "core/machines/section_steel/section_outline.h"

#include <optional>

namespace cutcell::section_steel {

class EndCut;

struct TorchBody {
    double length_mm = 150;
    double radius_mm = 12;
};

struct TorchHit {
    double behind_mm = 0; // along the axis from the tip
    Vec3 at{0, 0, 0};     // the axis point whose cylinder touches the section
};

// The first point (from the tip) where the body meets the section, nullopt when it is clear.
std::optional<TorchHit> torchHit(const EndCut& cut, const TorchBody& body, const Vec3& tip,
                                 const Vec3& torch, bool offcutPresent);

} // namespace cutcell::section_steel
