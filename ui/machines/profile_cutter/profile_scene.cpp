#include "ui/machines/profile_cutter/profile_scene.h"

#include "core/job/job.h"
#include "core/machines/profile_cutter/profile_cutter.h"

#include <algorithm>
#include <cmath>

namespace cutcell::view3d {
namespace {

// Height of the pipe axis above the floor beyond the pipe's radius (chuck stand).
constexpr double kStandHeight_mm = 400;
// Torch drawn from the tip back along its axis.
constexpr double kTorchLength_mm = 160;

} // namespace

SceneModel buildProfileCutterScene(const Job& job) {
    const ProfileCut cut = computeProfileCut(job);
    SceneModel m;
    m.title = job.name;
    m.axisCount = 2;
    m.mount = ToolMount::LinearCarriage;
    m.chuckAxis = 0;
    m.carriageAxis = 1;

    const bool branchEnd = cut.target == CutTarget::Branch;
    const PipeSpec& pipe = branchEnd ? job.branch_pipe : job.main_pipe;
    const double r = cut.work_radius_mm;
    // The drawn tube spans the cut's X range and the pipe's length, from the chuck (X = 0).
    double xMin = 0, xMax = pipe.length_mm;
    for (const ProfilePoint& p : cut.points) {
        xMin = std::min(xMin, p.x_mm);
        xMax = std::max(xMax, p.x_mm);
    }
    m.workPipe = {r, pipe.wall_mm, xMax - xMin};
    m.workPipeCentreZ_mm = (xMin + xMax) / 2;

    // Work (x, y, z) -> world (Y, Z, X): pipe axis along world X, work +y up at A = 0.
    const double axisHeight = r + kStandHeight_mm;
    Pose base = Pose::Identity();
    base.linear().col(0) = Vec3::UnitY();
    base.linear().col(1) = Vec3::UnitZ();
    base.linear().col(2) = Vec3::UnitX();
    // The view puts the chuck at the tube's end farther from the world origin: shift the pipe
    // along -X so that end is X = 0 (the chuck end of the seed's l), the cut end near the origin.
    base.translation() = Vec3(-(xMax + 200), 0, axisHeight);
    m.baseFromWorkAtZero = base;

    // The torch tip at X = 0 touches the top generatrix; the carriage runs along the pipe axis.
    m.carriageOrigin = base * Vec3(0, r, 0);
    m.carriageDirection = base.linear() * Vec3::UnitZ();
    m.carriageApproach = -Vec3::UnitZ();
    m.toolLength_mm = kTorchLength_mm;

    m.pathWork.reserve(cut.points.size() + 1);
    m.approachWork.reserve(cut.points.size() + 1);
    for (size_t i = 0; i <= cut.points.size() && !cut.points.empty(); ++i) {
        const ProfilePoint p = cut.closedAt(i); // closed: the last point repeats the first
        const double a = deg2rad(p.a_deg);
        const Vec3 onPipe(r * std::sin(a), r * std::cos(a), p.x_mm);
        m.pathWork.push_back(onPipe);
        m.approachWork.push_back(-Vec3(onPipe.x(), onPipe.y(), 0).normalized()); // radial
    }
    m.reachable.assign(m.pathWork.size(), 1);
    const std::string problem = travelProblem(job, cut);
    if (!problem.empty()) {
        for (size_t i = 0; i < m.pathWork.size(); ++i) {
            const double x = m.pathWork[i].z();
            if (x < 0 || x > profileCutterSpecOrDefault(job).x_travel_mm) {
                m.reachable[i] = 0;
                if (m.firstUnreachable < 0) m.firstUnreachable = static_cast<int>(i);
            }
        }
    }
    m.floorZ_mm = 0;
    m.homeQ = JointVector::Zero();
    if (!cut.points.empty()) {
        m.homeQ[0] = deg2rad(cut.points.front().a_deg);
        m.homeQ[1] = cut.points.front().x_mm;
    }
    return m;
}

} // namespace cutcell::view3d
