#pragma once
// Reading and writing the section-steel `machine` section (SectionReader: unknown keys are
// refused with the key path) and checking its ranges (key, value, unit, limit).
#include "core/job/field_table.h"
#include "core/job/issue_checker.h"
#include "core/job/section_reader.h"
#include "core/machines/section_steel/section_steel_spec.h"

namespace cutcell::section_steel {

// The section's keys after `section`, once each, with unit, range and label
// (core/job/field_table.h): reading, writing, range checks and the form's rows.
std::span<const SectionField<SectionSteelSpec>> sectionSteelFields();
SectionSteelSpec readSteelSection(SectionReader& m);
void writeSteelSection(const SectionSteelSpec& s, json::Object& out);
void checkSteelSpec(IssueChecker& c, const SectionSteelSpec& s, double periodS);

} // namespace cutcell::section_steel
