#include "core/machines/profile_cutter/profile_cutter.h"

#include "core/common/c_format.h"
#include "core/machine/pipe_joint_section.h"
#include "core/machines/profile_cutter/profile_kerf.h"
#include "core/process/process_spec.h"

namespace cutcell {

ProfileCut computeProfileEdge(const Job& job, int n) {
    return computeProfileCut(job, jointExtrasOf(job), n);
}

double profileKerfMm(const Job& job) {
    if (!job.process.used) return 0;
    const ProcessSettings s = resolveProcess(job.process, cutPartWallMm(job));
    return s.ok() ? s.kerfMm() : 0.0;
}

ProfileCut computeProfileCut(const Job& job, int n) {
    ProfileCut cut = computeProfileEdge(job, n);
    const double kerf = profileKerfMm(job);
    if (kerf > 0)
        if (const Outcome o = compensateProfileKerf(cut, kerf); !o.ok())
            cut.kerf_problem = "kerf compensation: " + o.message;
    return cut;
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
