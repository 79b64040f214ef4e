#include "core/job/drive_fields.h"

namespace cutcell {
namespace {

constexpr FieldCheck kRange = FieldCheck::Range, kPositive = FieldCheck::Positive;

// Physical ranges of the drives: far beyond any joint of a cutting machine, but finite, so the
// discretised controller and plant stay finite numbers.
// clang-format off
const RowField<PidGains> kGains[] = {
    {.key = "kp_nm_per_rad", .unit = "N m/rad", .label = "Kp", .lo = 0, .hi = 1e6,
     .check = kRange, .decimals = 2, .number = [](PidGains& g) -> double& { return g.kp; }},
    {.key = "ki_nm_per_rad_s", .unit = "N m/(rad s)", .label = "Ki", .lo = 0, .hi = 1e8,
     .check = kRange, .decimals = 1, .number = [](PidGains& g) -> double& { return g.ki; }},
    {.key = "kd_nm_s_per_rad", .unit = "N m s/rad", .label = "Kd", .lo = 0, .hi = 1e5,
     .check = kRange, .decimals = 3, .number = [](PidGains& g) -> double& { return g.kd; }},
    {.key = "tau_f_s", .unit = "s", .label = "tau_f", .lo = 1e-5, .hi = 1,
     .check = kPositive, .decimals = 4, .number = [](PidGains& g) -> double& { return g.tau_f; }},
};
const RowField<JointPlantParams> kPlant[] = {
    {.key = "inertia_kg_m2", .unit = "kg m^2", .label = "Inertia", .lo = 1e-5, .hi = 1e4,
     .check = kPositive, .decimals = 4,
     .number = [](JointPlantParams& p) -> double& { return p.inertia_kg_m2; }},
    {.key = "viscous_nm_s_per_rad", .unit = "N m s/rad", .label = "Viscous", .lo = 0, .hi = 1e5,
     .check = kRange, .decimals = 3,
     .number = [](JointPlantParams& p) -> double& { return p.viscous_nm_s_per_rad; }},
    {.key = "torque_limit_nm", .unit = "N m", .label = "Torque limit", .lo = 1e-3, .hi = 1e5,
     .check = kPositive, .decimals = 2,
     .number = [](JointPlantParams& p) -> double& { return p.torque_limit_nm; }},
};
// clang-format on

} // namespace

std::span<const RowField<PidGains>> pidGainFields() {
    return kGains;
}

std::span<const RowField<JointPlantParams>> jointPlantFields() {
    return kPlant;
}

} // namespace cutcell
