// `cutcell-cli fk` / `ik` for the pipe-cutting robot: its one arm ("arm", theta1..theta5), in
// the robot base frame {0}; with the chuck angle theta0 also where the tip is on the pipe.
#include "core/machines/pipe_robot/pipe_robot.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"

#include <cmath>

namespace cutcell {

namespace {

json::Value vec(const Vec3& v) {
    return json::Array{v.x(), v.y(), v.z()};
}

Outcome checkArm(const std::string& arm) {
    if (arm.empty() || arm == "arm") return Outcome::done();
    return Outcome::refuse("--arm = " + json::quote(arm) + " is not this machine's arm (\"arm\")");
}

Outcome checkFinite(const std::vector<double>& v, const char* option) {
    for (size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i]))
            return Outcome::refuse(std::string(option) + ": value " + std::to_string(i + 1) +
                                   " is not finite");
    return Outcome::done();
}

// The arm and the values of an option (--joints, --pose): Ok, or the first refusal.
Outcome checkRequest(const std::string& arm, const std::vector<double>& v, const char* option) {
    if (Outcome o = checkArm(arm); !o.ok()) return o;
    return checkFinite(v, option);
}

} // namespace

Outcome PipeRobotModule::forwardKinematics(const Job& job, const std::string& arm,
                                           const std::vector<double>& q, json::Value* out) const {
    if (Outcome o = checkRequest(arm, q, "--joints"); !o.ok()) return o;
    if (q.size() != kArmJointCount && q.size() != kAxisCount)
        return Outcome::refuse("--joints needs 5 values theta1..theta5 (deg), or 6 with the "
                               "chuck angle theta0 first; found " +
                               std::to_string(q.size()));
    const PipeRobot robot(pipeRobotSpec(job).dh);
    const size_t first = q.size() == kAxisCount ? 1 : 0;
    ArmVector arm5;
    for (int j = 0; j < kArmJointCount; ++j)
        arm5[j] = deg2rad(q[first + static_cast<size_t>(j)]);
    const Pose tool = robot.forward(arm5);
    json::Object o{{"arm", "arm"},
                   {"frame", "robot base {0} (Z0 up, the pipe axis on X0), mm"},
                   {"tip_mm", vec(tool.translation())},
                   {"torch", vec(tool.linear().col(2))},
                   {"n", vec(tool.linear().col(0))}};
    // Joint limits: FK answers for any angle, but says which joints are outside theirs.
    json::Array outside;
    for (int j = 0; j < kArmJointCount; ++j)
        if (!robot.withinLimits(j + 1, arm5[j]))
            outside.emplace_back("theta" + std::to_string(j + 1));
    o.emplace_back("joints_outside_limits", outside);
    if (first == 1) {
        const double theta0 = deg2rad(q[0]);
        o.emplace_back("tip_on_work_mm", vec(robot.workFromBase(theta0, tool.translation())));
        o.emplace_back("work_frame", "the work pipe at chuck angle theta0 (its axis z), mm");
    }
    *out = json::Value(std::move(o));
    return Outcome::done();
}

Outcome PipeRobotModule::inverseKinematics(const Job& job, const std::string& arm,
                                           const std::vector<double>& pose,
                                           json::Value* out) const {
    if (Outcome o = checkRequest(arm, pose, "--pose"); !o.ok()) return o;
    if (pose.size() != 6 && pose.size() != 7)
        return Outcome::refuse("--pose needs 6 values: x, y, z (mm), tx, ty, tz (torch "
                               "direction), and optionally the roll theta5 (deg); found " +
                               std::to_string(pose.size()));
    const Vec3 p(pose[0], pose[1], pose[2]);
    Vec3 t(pose[3], pose[4], pose[5]);
    if (!(t.norm() > 1e-9))
        return Outcome::refuse("--pose: the torch direction (tx, ty, tz) is zero");
    t.normalize();
    const double roll = pose.size() == 7 ? deg2rad(pose[6]) : 0.0;
    const PipeRobot robot(pipeRobotSpec(job).dh);
    const IkBranches all = robot.solveBranches(p, t, roll);
    json::Array branches;
    for (int b = 0; b < all.count; ++b) {
        const IkResult& r = all.branch[static_cast<size_t>(b)];
        json::Array joints;
        if (r.status != IkStatus::OutOfReach && r.status != IkStatus::OrientationUnreachable)
            for (int j = 0; j < kArmJointCount; ++j)
                joints.emplace_back(rad2deg(r.q[j]));
        branches.emplace_back(json::Object{{"joints_deg", joints},
                                           {"status", r.ok() ? std::string("ok") : describe(r)}});
    }
    *out = json::Object{{"arm", "arm"},
                        {"frame", "robot base {0}, mm"},
                        {"tip_mm", vec(p)},
                        {"torch", vec(t)},
                        {"branches", branches}};
    return Outcome::done();
}

} // namespace cutcell
