#pragma once
// The profile cutter's stepper keys (`machine.profile_cutter.*`) as a field table
// (core/job/field_table.h): each key once with its unit, range, label and decimals, for the
// reader, the writer, the range checks and the form.
#include "core/job/field_table.h"
#include "core/machines/profile_cutter/profile_cutter_spec.h"

#include <span>

namespace cutcell {

std::span<const SectionField<ProfileCutterSpec>> profileCutterFields();

} // namespace cutcell
