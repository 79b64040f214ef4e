#pragma once
// What differs between two jobs, key by key, as the job file spells the keys
// ("machine.carriage.max_speed_mm_s", "controller[0].kp_nm_per_rad"): the station asks who may
// open a job file that changes machine parameters (issue 25's user levels).
#include "core/job/job.h"

#include <string>
#include <vector>

namespace cutcell {

struct ChangedKey {
    std::string key;
    std::string from, to; // the values as JSON text; "" where the key is absent
};

// Every leaf (number, string, bool, null) of the two jobs' files that differs, in file order.
std::vector<ChangedKey> changedKeys(const Job& from, const Job& to);

} // namespace cutcell
