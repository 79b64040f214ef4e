#include "core/machines/profile_cutter/profile_cutter.h"

#include "core/common/c_format.h"

namespace cutcell {

ProfileCut computeProfileCut(const Job& job, int n) {
    return computeProfileCut(job, jointExtrasOf(job), n);
}

ProfileCut computeProfileCut(const Job& job) {
    return computeProfileCut(job, profileCutterSpecOrDefault(job).steps_per_rev_a);
}

std::string travelProblem(const Job& job, const ProfileCut& cut) {
    const double travel = profileCutterSpec(job).x_travel_mm;
    for (const auto& p : cut.points)
        if (p.x_mm < 0 || p.x_mm > travel) {
            return messageC("the cut needs X = %.3f mm (beta = %.2f deg), outside the carriage "
                            "travel 0 .. machine.profile_cutter.x_travel_mm = %.3f mm",
                            p.x_mm, p.beta_deg, travel);
        }
    return {};
}

} // namespace cutcell
