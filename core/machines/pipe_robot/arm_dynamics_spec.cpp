#include "core/machines/pipe_robot/arm_dynamics_spec.h"

namespace cutcell {
namespace {

constexpr FieldCheck kRange = FieldCheck::Range;
constexpr FieldCheck kPositive = FieldCheck::Positive;

// clang-format off
const RowField<ArmLinkRow> kLinkFields[] = {
    {.key = "mass_kg", .unit = "kg", .label = "mass", .lo = 0, .hi = 500, .check = kRange,
     .decimals = 3, .number = [](ArmLinkRow& r) -> double& { return r.mass_kg; }},
    {.key = "com_x_mm", .unit = "mm", .label = "com x", .lo = -5000, .hi = 5000, .check = kRange,
     .decimals = 1, .number = [](ArmLinkRow& r) -> double& { return r.com_x_mm; }},
    {.key = "com_y_mm", .unit = "mm", .label = "com y", .lo = -5000, .hi = 5000, .check = kRange,
     .decimals = 1, .number = [](ArmLinkRow& r) -> double& { return r.com_y_mm; }},
    {.key = "com_z_mm", .unit = "mm", .label = "com z", .lo = -5000, .hi = 5000, .check = kRange,
     .decimals = 1, .number = [](ArmLinkRow& r) -> double& { return r.com_z_mm; }},
    {.key = "ixx_kg_cm2", .unit = "kg cm^2", .label = "Ixx", .lo = 0, .hi = 1e7, .check = kRange,
     .decimals = 2, .number = [](ArmLinkRow& r) -> double& { return r.ixx_kg_cm2; }},
    {.key = "iyy_kg_cm2", .unit = "kg cm^2", .label = "Iyy", .lo = 0, .hi = 1e7, .check = kRange,
     .decimals = 2, .number = [](ArmLinkRow& r) -> double& { return r.iyy_kg_cm2; }},
    {.key = "izz_kg_cm2", .unit = "kg cm^2", .label = "Izz", .lo = 0, .hi = 1e7, .check = kRange,
     .decimals = 2, .number = [](ArmLinkRow& r) -> double& { return r.izz_kg_cm2; }},
    {.key = "ixy_kg_cm2", .unit = "kg cm^2", .label = "Ixy", .lo = -1e7, .hi = 1e7,
     .check = kRange, .decimals = 2, .number = [](ArmLinkRow& r) -> double& { return r.ixy_kg_cm2; },
     .absent = 0},
    {.key = "ixz_kg_cm2", .unit = "kg cm^2", .label = "Ixz", .lo = -1e7, .hi = 1e7,
     .check = kRange, .decimals = 2, .number = [](ArmLinkRow& r) -> double& { return r.ixz_kg_cm2; },
     .absent = 0},
    {.key = "iyz_kg_cm2", .unit = "kg cm^2", .label = "Iyz", .lo = -1e7, .hi = 1e7,
     .check = kRange, .decimals = 2, .number = [](ArmLinkRow& r) -> double& { return r.iyz_kg_cm2; },
     .absent = 0},
};

const RowField<DriveTrainRow> kDriveFields[] = {
    {.key = "gear_ratio", .unit = "", .label = "gear N", .lo = 1, .hi = 1000, .check = kRange,
     .decimals = 1, .number = [](DriveTrainRow& r) -> double& { return r.gear_ratio; }},
    {.key = "rotor_inertia_g_cm2", .unit = "g cm^2", .label = "rotor J", .lo = 0, .hi = 1e6,
     .check = kRange, .decimals = 1,
     .number = [](DriveTrainRow& r) -> double& { return r.rotor_inertia_g_cm2; }},
    {.key = "viscous_nm_s_per_rad", .unit = "N m s/rad", .label = "viscous", .lo = 0, .hi = 1e4,
     .check = kRange, .decimals = 3,
     .number = [](DriveTrainRow& r) -> double& { return r.viscous_nm_s_per_rad; }},
    {.key = "coulomb_nm", .unit = "N m", .label = "Coulomb", .lo = 0, .hi = 1e4, .check = kRange,
     .decimals = 3, .number = [](DriveTrainRow& r) -> double& { return r.coulomb_nm; }},
    {.key = "torque_limit_nm", .unit = "N m", .label = "torque limit", .lo = 0, .hi = 1e5,
     .check = kPositive, .decimals = 1,
     .number = [](DriveTrainRow& r) -> double& { return r.torque_limit_nm; }},
};
// clang-format on

} // namespace

const char* toString(PlantModel m) {
    return m == PlantModel::Linear ? "linear" : "rigid_body";
}

std::span<const RowField<ArmLinkRow>> armLinkFields() {
    return kLinkFields;
}

std::span<const RowField<DriveTrainRow>> driveTrainFields() {
    return kDriveFields;
}

} // namespace cutcell
