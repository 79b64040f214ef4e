#include "ui/view3d/scene_model.h"

#include <algorithm>
#include <cmath>

namespace cutcell::view3d {

Pose SceneModel::baseFromWork(const JointVector& q) const {
    const double a = (chuckAxis >= 0 && chuckAxis < kMaxAxes) ? q[chuckAxis] : 0.0;
    return baseFromWorkAtZero * Eigen::AngleAxisd(a, Vec3::UnitZ());
}

Pose SceneModel::toolPose(const JointVector& q) const {
    if (mount == ToolMount::DhArm) return armChain.forward(q.data() + armFirstAxis);
    Pose p = Pose::Identity();
    // Any frame with the torch axis as z: x chosen perpendicular to it.
    const Vec3 z = carriageApproach.normalized();
    Vec3 x = z.unitOrthogonal();
    p.linear().col(0) = x;
    p.linear().col(1) = z.cross(x);
    p.linear().col(2) = z;
    const double travel = (carriageAxis >= 0 && carriageAxis < kMaxAxes) ? q[carriageAxis] : 0.0;
    p.translation() = carriageOrigin + travel * carriageDirection.normalized();
    return p;
}

std::vector<Pose> SceneModel::armFrames(const JointVector& q) const {
    if (mount != ToolMount::DhArm) return {};
    std::vector<Pose> frames(armChain.size() + 1, Pose::Identity());
    armChain.frames(q.data() + armFirstAxis, frames.data());
    return frames;
}

Vec3 SceneModel::pathPointWorld(size_t i, const JointVector& q) const {
    return baseFromWork(q) * pathWork[i];
}

size_t SceneModel::unreachableCount() const {
    return static_cast<size_t>(std::count(reachable.begin(), reachable.end(), std::uint8_t{0}));
}

} // namespace cutcell::view3d
