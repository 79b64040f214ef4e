#pragma once
// What a torch machine's lead planning starts from (issue 24): the leads the job asks for (an
// overlap alone counts) and the process resolved at the part's wall, with the chart's refusal
// and the missing heights already turned into a problem. Shared by the pipe machines' leads
// (robot_lead, profile_lead); each adds its own rules after it.
#include "core/process/process_spec.h"

#include <string>

namespace cutcell {

struct LeadRequest {
    bool used = false; // a lead-in, a lead-out or an overlap is asked for
    LeadSpec in, out;
    ProcessSettings settings;         // valid when used and problem is empty
    std::string problem, problem_key; // the chart refused, or a lead needs a height it lacks
};

LeadRequest requestLeads(const ProcessSpec& spec, double partWall_mm);

} // namespace cutcell
