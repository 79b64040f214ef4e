#include "core/machines/pipe_robot/pipe_robot_spec.h"

#include "core/machines/pipe_robot/arm_construction.h"

namespace cutcell {
namespace {

constexpr FieldCheck kRange = FieldCheck::Range;

// clang-format off
const RowField<DhRow> kDhFields[] = {
    {.key = "alpha_deg", .unit = "deg", .label = "alpha", .lo = -360, .hi = 360, .check = kRange,
     .decimals = 1, .number = [](DhRow& r) -> double& { return r.alpha_deg; }},
    {.key = "a_mm", .unit = "mm", .label = "a", .lo = -5000, .hi = 5000, .check = kRange,
     .decimals = 1, .number = [](DhRow& r) -> double& { return r.a_mm; }},
    {.key = "d_mm", .unit = "mm", .label = "d", .lo = -5000, .hi = 5000, .check = kRange,
     .decimals = 1, .number = [](DhRow& r) -> double& { return r.d_mm; }},
    {.key = "theta_offset_deg", .unit = "deg", .label = "offset", .lo = -360, .hi = 360,
     .check = kRange, .decimals = 1,
     .number = [](DhRow& r) -> double& { return r.theta_offset_deg; }, .absent = 0},
    {.key = "min_deg", .unit = "deg", .label = "min", .lo = -360, .hi = 360, .check = kRange,
     .decimals = 1, .number = [](DhRow& r) -> double& { return r.min_deg; }},
    {.key = "max_deg", .unit = "deg", .label = "max", .lo = -360, .hi = 360, .check = kRange,
     .decimals = 1, .number = [](DhRow& r) -> double& { return r.max_deg; }},
};
// clang-format on

} // namespace

const char* toString(CutMethod m) {
    return m == CutMethod::StaticPipe ? "static_pipe" : "rotating_pipe";
}

std::array<DhRow, kAxisCount> seedDhTable() {
    // alpha_deg, a_mm, d_mm, theta_offset_deg, min_deg, max_deg (seed Table 1).
    return {{{90, 0, 260, 0, -180, 180},
             {90, 0, 371, 0, -140, 140},
             {0, 157, 0, 0, -45, 45},
             {0, 120, 0, 0, -90, 90},
             {90, 50, 0, 0, -145, 90},
             {0, 0, 210, 0, -180, 180}}};
}

std::span<const RowField<DhRow>> dhRowFields() {
    return kDhFields;
}

std::array<ArmLinkRow, kArmJointCount> PipeRobotSpec::defaultArmLinks() {
    return derivedArmLinks(seedDhTable());
}

std::array<DriveTrainRow, kAxisCount> PipeRobotSpec::defaultDrives() {
    return defaultDriveTrains();
}

ChuckLoad PipeRobotSpec::defaultChuck() {
    return defaultChuckLoad();
}

const PipeRobotSpec& pipeRobotSpec(const Job& job) {
    return readSpec<PipeRobotSpec>(job.machine_spec, "the pipe robot's");
}

PipeRobotSpec& pipeRobotSpec(Job& job) {
    return editSpec<PipeRobotSpec>(job.machine_spec, "the pipe robot's");
}

} // namespace cutcell
