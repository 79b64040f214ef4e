#include "core/process/lead_request.h"

namespace cutcell {

LeadRequest requestLeads(const ProcessSpec& spec, double partWall_mm) {
    LeadRequest r;
    if (!spec.used) return r;
    r.in = spec.lead_in;
    r.out = spec.lead_out;
    r.used = r.in.used() || r.out.used() || r.out.overlap_mm > 0; // overlap alone too
    if (!r.used) return r;
    r.settings = resolveProcess(spec, partWall_mm);
    if (!r.settings.ok()) {
        r.problem = r.settings.outcome.message;
        r.problem_key = r.settings.outcome.key;
    } else if (std::string p = leadHeightProblem(spec, r.settings); !p.empty()) {
        r.problem = std::move(p);
        r.problem_key = leadHeightKey(spec, r.settings);
    }
    return r;
}

} // namespace cutcell
