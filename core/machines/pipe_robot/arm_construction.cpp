#include "core/machines/pipe_robot/arm_construction.h"

#include "core/common/types.h"
#include "core/dynamics/chain_dynamics.h"

#include <cmath>

namespace cutcell {
namespace {

// A body's mass, centre of mass and inertia about it, summed as bodies are added.
struct Body {
    double m = 0;
    Vec3 c = Vec3::Zero();
    Mat3 I = Mat3::Zero();
};

Body add(const Body& a, const Body& b) {
    Body s;
    s.m = a.m + b.m;
    if (s.m <= 0) return s;
    s.c = (a.m * a.c + b.m * b.c) / s.m;
    s.I = a.I + pointMassInertia(a.m, a.c - s.c) + b.I + pointMassInertia(b.m, b.c - s.c);
    return s;
}

// A tube of mass m between points p and q (m), radii ro > ri.
Body tube(double m, const Vec3& p, const Vec3& q, double ro, double ri) {
    Body b;
    b.m = m;
    b.c = 0.5 * (p + q);
    const double L = (q - p).norm();
    const Vec3 u = L > 0 ? Vec3((q - p) / L) : Vec3::UnitZ();
    const double axial = 0.5 * m * (ro * ro + ri * ri);
    const double transverse = m * (3 * (ro * ro + ri * ri) + L * L) / 12;
    b.I = transverse * (Mat3::Identity() - u * u.transpose()) + axial * u * u.transpose();
    return b;
}

double tubeMass(double density, double length, double ro, double ri) {
    return density * kPi * (ro * ro - ri * ri) * length;
}

ArmLinkRow toRow(const Body& b) {
    constexpr double kgCm2 = 1e4; // kg m^2 -> kg cm^2
    ArmLinkRow r;
    r.mass_kg = b.m;
    r.com_x_mm = b.c.x() * 1e3;
    r.com_y_mm = b.c.y() * 1e3;
    r.com_z_mm = b.c.z() * 1e3;
    r.ixx_kg_cm2 = b.I(0, 0) * kgCm2;
    r.iyy_kg_cm2 = b.I(1, 1) * kgCm2;
    r.izz_kg_cm2 = b.I(2, 2) * kgCm2;
    r.ixy_kg_cm2 = b.I(0, 1) * kgCm2;
    r.ixz_kg_cm2 = b.I(0, 2) * kgCm2;
    r.iyz_kg_cm2 = b.I(1, 2) * kgCm2;
    return r;
}

} // namespace

std::array<ArmLinkRow, kArmJointCount> derivedArmLinks(const std::array<DhRow, kAxisCount>& dh,
                                                       const ArmConstruction& c) {
    std::array<ArmLinkRow, kArmJointCount> out{};
    for (int i = 1; i <= kArmJointCount; ++i) {
        const DhRow& r = dh[static_cast<size_t>(i)];
        const double a = r.a_mm * 1e-3, d = r.d_mm * 1e-3, al = deg2rad(r.alpha_deg);
        // Frame i-1's origin seen from frame i: the link spans from there to frame i's origin.
        const Vec3 from(-a, -d * std::sin(al), -d * std::cos(al));
        const double length = from.norm();
        Body link;
        if (i < kArmJointCount) {
            const TubeSpec& t = c.link_tube[static_cast<size_t>(i - 1)];
            const double ro = 0.5e-3 * t.outer_diameter_mm;
            const double ri = std::max(0.0, ro - 1e-3 * t.wall_mm);
            link = tube(tubeMass(c.density_kg_m3, length, ro, ri), from, Vec3::Zero(), ro, ri);
            // The next joint's actuator on that joint's axis (z_i) at this frame's origin.
            const auto k = static_cast<size_t>(i - 1);
            const double h = 1e-3 * c.actuator_length_mm[k];
            const double ra = 0.5e-3 * c.actuator_diameter_mm[k];
            link = add(link,
                       tube(c.actuator_mass_kg[k], Vec3(0, 0, -h / 2), Vec3(0, 0, h / 2), ra, 0));
        } else {
            const double ro = 0.5e-3 * c.torch_diameter_mm;
            link = tube(c.torch_mass_kg, from, Vec3::Zero(), ro, 0);
        }
        out[static_cast<size_t>(i - 1)] = toRow(link);
    }
    return out;
}

std::array<DriveTrainRow, kAxisCount> defaultDriveTrains() {
    // gear N, rotor J (g cm^2, motor side), viscous (N m s/rad), Coulomb (N m), limit (N m).
    return {{{50, 120, 0.5, 0.5, 20},
             {100, 60, 1.0, 1.0, 60},
             {100, 60, 1.0, 1.0, 60},
             {100, 30, 0.5, 0.6, 30},
             {100, 12, 0.2, 0.3, 15},
             {100, 6, 0.1, 0.15, 10}}};
}

ChuckLoad defaultChuckLoad() {
    return {0.03, 7850};
}

} // namespace cutcell
