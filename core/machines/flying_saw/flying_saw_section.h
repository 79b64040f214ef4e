#pragma once
// Reading, writing and checking the flying saw's `machine` section (keys in README).
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machines/flying_saw/flying_saw_spec.h"

#include <vector>

namespace cutcell {

FlyingSawSpec readFlyingSawSection(const json::Value& section); // throws JobError
json::Object writeFlyingSawSection(const FlyingSawSpec& spec);  // without "kind"
std::vector<JobIssue> checkFlyingSawSpec(const FlyingSawSpec& spec);

} // namespace cutcell
