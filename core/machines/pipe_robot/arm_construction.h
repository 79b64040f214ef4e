#pragma once
// The default mechanics of the seed-000 arm. The seed gives no masses ("five harmonic driver
// motors", a SolidWorks model not printed): these are derived from the DH lengths and a stated
// construction - aluminium tube links, a harmonic-drive actuator at each joint carried by the link
// before it, the torch as the last link - so that every figure can be traced (README, "The arm's
// mechanics"). The job keeps the result (robot.links[], robot.drives[]) and may change it.
#include "core/machines/pipe_robot/arm_dynamics_spec.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"

#include <array>

namespace cutcell {

struct TubeSpec {
    double outer_diameter_mm = 0;
    double wall_mm = 0; // wall >= radius: a solid cylinder
};

struct ArmConstruction {
    double density_kg_m3 = 2700; // aluminium 6061
    // Link i's tube runs from frame i-1's origin to frame i's (the DH offset a_i, d_i).
    std::array<TubeSpec, kArmJointCount - 1> link_tube{{{60, 4}, {50, 3}, {40, 3}, {40, 3}}};
    // The actuator of joint i + 1 (gear, motor, housing) sits on joint i + 1's axis at frame i's
    // origin, a solid cylinder carried by link i (i = 1..4).
    std::array<double, kArmJointCount - 1> actuator_mass_kg{1.2, 1.0, 0.6, 0.4};
    std::array<double, kArmJointCount - 1> actuator_diameter_mm{70, 60, 50, 40};
    std::array<double, kArmJointCount - 1> actuator_length_mm{80, 70, 60, 50};
    // Link 5 is the torch and its holder, from the wrist to the tip (d5), a uniform rod.
    double torch_mass_kg = 0.9;
    double torch_diameter_mm = 35;
};

// Links 1..5 (rows 0..4) from the DH table (rows 1..5 of `dh`) and the construction.
std::array<ArmLinkRow, kArmJointCount> derivedArmLinks(const std::array<DhRow, kAxisCount>& dh,
                                                       const ArmConstruction& c = {});
// The drive trains of the chuck and the five joints (README: typical figures of the class).
std::array<DriveTrainRow, kAxisCount> defaultDriveTrains();
ChuckLoad defaultChuckLoad();

} // namespace cutcell
