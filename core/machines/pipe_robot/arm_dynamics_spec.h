#pragma once
// The pipe robot's mechanics for the rigid-body plant: per arm link its mass, centre of mass and
// inertia tensor (robot.links[], in the link's DH frame), per axis its drive train (gear ratio,
// motor rotor inertia, friction, torque limit: robot.drives[]), the chuck's own inertia and the
// density of the pipe it turns. The default figures are derived from the DH lengths and a
// documented construction (arm_construction.h; every number's origin is in the README).
#include "core/job/row_table.h"

#include <array>
#include <span>

namespace cutcell {

// Which mechanics the simulated drives and the offline simulation run: one linear plant per
// axis (J q'' + b q' = u, the job's plant[] rows) or the arm as coupled rigid bodies.
enum class PlantModel { Linear, RigidBody };
const char* toString(PlantModel m);

struct ArmLinkRow {
    double mass_kg = 0;
    double com_x_mm = 0, com_y_mm = 0, com_z_mm = 0;
    // About the centre of mass, in the link's DH frame (kg cm^2 reads better than 1e-4 kg m^2).
    double ixx_kg_cm2 = 0, iyy_kg_cm2 = 0, izz_kg_cm2 = 0;
    double ixy_kg_cm2 = 0, ixz_kg_cm2 = 0, iyz_kg_cm2 = 0;
};

struct DriveTrainRow {
    double gear_ratio = 1;
    double rotor_inertia_g_cm2 = 0;  // motor + wave generator, motor side
    double viscous_nm_s_per_rad = 0; // joint side
    double coulomb_nm = 0;           // joint side
    double torque_limit_nm = 0;      // joint side
};

struct ChuckLoad {
    double inertia_kg_m2 = 0;         // spindle, chuck body and jaws about the pipe axis
    double pipe_density_kg_m3 = 7850; // the pipe in the chuck (steel)
};

std::span<const RowField<ArmLinkRow>> armLinkFields();
std::span<const RowField<DriveTrainRow>> driveTrainFields();

} // namespace cutcell
