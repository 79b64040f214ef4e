#include "core/machine/counts_reach.h"

#include "core/common/c_format.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cutcell {

namespace {
constexpr double kInt32Counts = 2147483647.0;
} // namespace

double programReach(const MotionProgram& p, int axis) {
    const Eigen::Index i = axis;
    double reach = std::max(std::fabs(p.start_position[i]), std::fabs(p.reference[i]));
    if (p.source_kind == MotionSourceKind::JointSpline) {
        for (size_t k = 0; k < p.spline.knotCount(); ++k)
            reach = std::max(reach, std::fabs(p.spline.knot(k)[i]));
        return reach;
    }
    if (p.endless_reach[i] > 0) return std::max(reach, p.endless_reach[i]);
    return std::max({reach, std::fabs(p.min_position[i]), std::fabs(p.max_position[i])});
}

Outcome countsFitProgram(const Job& job, const MotionProgram& p) {
    for (int i = 0; i < p.axis_count && i < kMaxAxes; ++i) {
        const bool linear = p.axis_linear[static_cast<size_t>(i)];
        const double perUnit = job.devices.counts_per_unit[static_cast<size_t>(i)];
        // counts_per_unit is per degree on a rotary axis; positions are in rad.
        const double reach =
            linear ? programReach(p, i) : programReach(p, i) * 180 / std::numbers::pi;
        const double counts = reach * perUnit;
        if (counts <= kInt32Counts) continue;
        const char* unit = linear ? "mm" : "deg";
        const std::string key = "devices.counts_per_unit[" + std::to_string(i) + "]";
        return Outcome::refuse(
            messageC("%s = %.6g counts/%s: axis %d (%s) goes as far as %.6g %s in this run, "
                     "%.4g counts, beyond a drive's 32-bit position (%.0f counts); at most "
                     "%.6g counts/%s, or a shorter run",
                     key.c_str(), perUnit, unit, i, p.axis_names[static_cast<size_t>(i)].c_str(),
                     reach, unit, counts, kInt32Counts,
                     std::floor(kInt32Counts / reach * 1e3) / 1e3, unit),
            key);
    }
    return Outcome::done();
}

} // namespace cutcell
