#pragma once
// Reading and writing the section-steel `machine` section (SectionReader: unknown keys are
// refused with the key path) and checking its ranges (key, value, unit, limit).
#include "core/job/issue_checker.h"
#include "core/job/section_reader.h"
#include "core/machines/section_steel/section_steel_spec.h"

namespace cutcell::section_steel {

SectionSteelSpec readSteelSection(SectionReader& m);
void writeSteelSection(const SectionSteelSpec& s, json::Object& out);
void checkSteelSpec(IssueChecker& c, const SectionSteelSpec& s, double periodS);

} // namespace cutcell::section_steel
