#pragma once
// The job's process section as data (core/process/process_spec.h reads, writes, resolves and
// checks it): the cut chart's entry a torch machine cuts with and the operator's overrides.
#include "core/process/cut_chart.h"

#include <optional>
#include <string>

namespace cutcell {

struct ProcessSpec {
    bool used = false; // the section is in the job
    CutProcess process = CutProcess::Plasma;
    std::string material;
    std::string consumable;
    std::optional<double> thickness_mm; // absent: the wall of the part being cut
    CutRow override;                    // the figures set over the chart's (thickness never)
    bool operator==(const ProcessSpec&) const = default;
};

} // namespace cutcell
