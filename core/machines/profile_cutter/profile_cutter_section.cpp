#include "core/machines/profile_cutter/profile_cutter_section.h"

namespace cutcell {
namespace {

using Field = SectionField<ProfileCutterSpec>;
using S = ProfileCutterSpec;
constexpr FieldCheck kRange = FieldCheck::Range;

// Every stepper key, once (the file is written in this order). The hole's position is bounded
// by the main pipe's length: checked in ProfileCutterModule::validate().
// clang-format off
const Field kFields[] = {
    {.key = "profile_cutter.steps_per_rev_a", .unit = "steps/rev",
     .label = "Steps per revolution (n)", .lo = 8, .hi = 100000, .check = kRange,
     .integer = [](S& s) -> int& { return s.steps_per_rev_a; }},
    {.key = "profile_cutter.pulses_per_step_a", .unit = "pulses/step", .label = "Pulses per step",
     .lo = 1, .hi = 100000, .check = kRange,
     .integer = [](S& s) -> int& { return s.pulses_per_step_a; }},
    {.key = "profile_cutter.mm_per_pulse_x", .unit = "mm/pulse", .label = "Travel per pulse",
     .lo = 1e-5, .hi = 1, .check = kRange, .decimals = 5,
     .number = [](S& s) -> double& { return s.mm_per_pulse_x; }},
    {.key = "profile_cutter.max_pulse_rate_hz", .unit = "Hz", .label = "Max. pulse rate per axis",
     .lo = 1, .hi = 1e7, .check = kRange, .decimals = 0,
     .number = [](S& s) -> double& { return s.max_pulse_rate_hz; }},
    {.key = "profile_cutter.pierce_s", .unit = "s", .label = "Pierce dwell", .lo = 0, .hi = 60,
     .check = kRange, .decimals = 2, .number = [](S& s) -> double& { return s.pierce_s; }},
    {.key = "profile_cutter.x_travel_mm", .unit = "mm", .label = "Carriage travel", .lo = 1,
     .hi = 100000, .check = kRange, .decimals = 1,
     .number = [](S& s) -> double& { return s.x_travel_mm; }},
    // Absent in the file: the middle of the main pipe (branch_position_auto).
    {.key = "profile_cutter.branch_position_mm", .unit = "mm", .label = "Branch axis at X (S)",
     .decimals = 1,
     .readCustom = [](SectionReader& r, const std::string& leaf, S& s) {
         s.branch_position_auto = !r.has(leaf);
         s.branch_position_mm = r.number(leaf, "mm", 0);
     },
     .writeCustom = [](const S& s) -> json::Value {
         return s.branch_position_auto ? json::Value() : json::Value(s.branch_position_mm);
     }},
};
// clang-format on

} // namespace

std::span<const SectionField<ProfileCutterSpec>> profileCutterFields() {
    return kFields;
}

} // namespace cutcell
