#pragma once
// Shared value types of the core: fixed-size joint vectors so the control cycle never allocates.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <numbers>

namespace cutcell {

// A machine has up to kMaxAxes axes; a JointVector holds one value per axis (axes past the
// machine's axis count are zero). Fixed size: no heap in the control cycle.
inline constexpr int kMaxAxes = 8;

using JointVector = Eigen::Matrix<double, kMaxAxes, 1>;

// The unit of an axis: rotary axes in rad (shown in deg), linear axes in mm.
enum class AxisUnit : std::uint8_t { Rotary, Linear };
inline constexpr const char* displayUnit(AxisUnit u) {
    return u == AxisUnit::Linear ? "mm" : "deg";
}
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
