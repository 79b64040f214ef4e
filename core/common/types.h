#pragma once
// Shared value types of the core: fixed-size joint vectors so the control cycle never allocates.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <numbers>

namespace cutcell {

// Axis 0 is the pipe chuck (the seed's theta0); axes 1..5 are the arm joints theta1..theta5.
inline constexpr int kAxisCount = 6;
inline constexpr int kArmJointCount = 5;

using JointVector = Eigen::Matrix<double, kAxisCount, 1>;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Pose = Eigen::Isometry3d;

inline constexpr double kPi = std::numbers::pi;
inline constexpr double deg2rad(double deg) {
    return deg * kPi / 180.0;
}
inline constexpr double rad2deg(double rad) {
    return rad * 180.0 / kPi;
}

} // namespace cutcell
