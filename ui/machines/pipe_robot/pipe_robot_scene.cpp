#include "ui/machines/pipe_robot/pipe_robot_scene.h"

#include "core/geometry/cut_path.h"
#include "core/machines/pipe_robot/pipe_robot.h"

#include <algorithm>
#include <cmath>

namespace cutcell::view3d {

SceneModel buildRobotScene(const Job& job, const CutPlan& plan) {
    SceneModel m;
    m.title = job.name;
    m.axisCount = kAxisCount;
    const CutGeometry geo(job);
    const PipeRobot robot(pipeRobotSpec(job).dh);
    const Pose workFromMain = geo.mainFromWork().inverse();
    const PipeIntersection& curve = geo.curve();

    // The branch frame in the main frame: origin on the main axis, z along the branch.
    Pose mainFromBranch = Pose::Identity();
    mainFromBranch.linear().col(0) = curve.branchY().cross(curve.branchAxis());
    mainFromBranch.linear().col(1) = curve.branchY();
    mainFromBranch.linear().col(2) = curve.branchAxis();
    mainFromBranch.translation() = curve.branchOrigin();
    // The main pipe is centred on the main frame's origin along its z axis.
    Pose mainFromMainStart = Pose::Identity();
    mainFromMainStart.translation() = Vec3(0, 0, -job.main_pipe.length_mm / 2);

    m.hasMatingPipe = true;
    if (job.cut.target == CutTarget::Main) {
        m.workPipe = {job.main_pipe.radius_mm, job.main_pipe.wall_mm, job.main_pipe.length_mm};
        m.workPipeCentreZ_mm = (workFromMain * Vec3::Zero()).z();
        m.matingPipe = {job.branch_pipe.radius_mm, job.branch_pipe.wall_mm,
                        job.branch_pipe.length_mm};
        m.workFromMating = workFromMain * mainFromBranch;
    } else {
        // The branch runs from the saddle outward along +z of its work frame; the raw stock
        // reaches a little past the cut (the scrap below the saddle).
        double zLow = 0;
        for (const PlannedPoint& k : plan.knots)
            zLow = std::min(zLow, k.cut.p_work.z());
        zLow -= 20.0;
        const double zHigh = job.branch_pipe.length_mm;
        m.workPipe = {job.branch_pipe.radius_mm, job.branch_pipe.wall_mm, zHigh - zLow};
        m.workPipeCentreZ_mm = (zLow + zHigh) / 2;
        m.matingPipe = {job.main_pipe.radius_mm, job.main_pipe.wall_mm, job.main_pipe.length_mm};
        m.workFromMating = workFromMain * mainFromMainStart;
    }
    m.chuckAxis = 0;
    m.baseFromWorkAtZero = robot.baseFromWork(0.0);

    const double maxDev = job.cut.max_direction_deviation_deg;
    m.pathWork.reserve(plan.knots.size());
    m.approachWork.reserve(plan.knots.size());
    m.reachable.reserve(plan.knots.size());
    for (const PlannedPoint& k : plan.knots) {
        m.pathWork.push_back(k.cut.p_work);
        m.approachWork.push_back(k.cut.approach_work);
        const bool ok =
            robot.withinLimits(0, k.chuck_rad) && k.ik.ok() && k.deviation_deg <= maxDev + 1e-9;
        if (!ok && m.firstUnreachable < 0)
            m.firstUnreachable = static_cast<int>(m.reachable.size());
        m.reachable.push_back(ok ? 1 : 0);
    }

    m.mount = ToolMount::DhArm;
    m.armChain = robot.arm();
    m.armFirstAxis = 1;
    m.toolLength_mm = std::max(50.0, std::fabs(pipeRobotSpec(job).dh.back().d_mm));

    // Floor below everything that can swing round with the chuck.
    const double swing =
        std::max(m.workPipe.radius_mm, m.hasMatingPipe ? m.matingPipe.length_mm : 0.0);
    m.floorZ_mm = -(swing + 60.0);
    if (!plan.knots.empty()) m.homeQ = plan.knots.front().q;
    return m;
}

} // namespace cutcell::view3d
