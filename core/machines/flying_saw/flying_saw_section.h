#pragma once
// Reading, writing and checking the flying saw's `machine` section (keys in README).
#include "core/job/field_table.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machines/flying_saw/flying_saw_spec.h"

#include <vector>

namespace cutcell {

// Every key of the section once, with unit, range and label (core/job/field_table.h).
std::span<const SectionField<FlyingSawSpec>> flyingSawFields();
FlyingSawSpec readFlyingSawSection(const json::Value& section); // throws JobError
json::Object writeFlyingSawSection(const FlyingSawSpec& spec);  // without "kind"
std::vector<JobIssue> checkFlyingSawSpec(const FlyingSawSpec& spec);

} // namespace cutcell
