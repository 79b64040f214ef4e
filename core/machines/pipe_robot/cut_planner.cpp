#include "core/machines/pipe_robot/cut_planner.h"
#include "core/common/c_format.h"
#include "core/machine/pipe_joint_section.h"
#include "core/process/kerf_offset.h"
#include "core/process/process_spec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cutcell {

namespace {

// Why the point cannot be cut, and where it is.
std::string pointProblem(size_t index, const PlannedPoint& p, const std::string& why) {
    return messageC("point %zu (phi = %.2f deg, s = %.2f mm, x/y/z = %.2f/%.2f/%.2f mm): %s", index,
                    rad2deg(p.cut.phi_rad), p.cut.s_mm, p.cut.p_main.x(), p.cut.p_main.y(),
                    p.cut.p_main.z(), why.c_str());
}

} // namespace

CutPlan planCut(const Job& job, const PlanOptions& options) {
    const PipeRobotSpec& spec = pipeRobotSpec(job);
    CutPlan plan;
    plan.method = spec.method;
    const CutGeometry geo(job);
    const PipeRobot robot(spec.dh);
    plan.length_mm = geo.length();
    const SpeedProfile profile(geo.length(), job.cut.speed_mm_s, job.cut.ramp_s);
    plan.cut_time_s = profile.duration();
    // Knots at equal time steps, about knot_spacing_mm apart at cutting speed.
    const int intervals =
        std::max(16, static_cast<int>(std::ceil(geo.length() / job.cut.knot_spacing_mm)));
    plan.knot_dt_s = plan.cut_time_s / intervals;
    plan.knots.resize(static_cast<size_t>(intervals) + 1);

    // Kerf compensation: the whole edge is checked once (the kerf against its curvature, the
    // torch against its tangent), then each knot's point moves to the torch centre.
    KerfPathSpec kerfSpec;
    std::string kerfProblem;
    if (job.process.used) {
        const ProcessSettings process = resolveProcess(job.process, cutPartWallMm(job));
        plan.kerf_mm = process.ok() ? process.kerfMm() : 0.0;
    }
    if (plan.kerf_mm > 0) {
        kerfSpec = kerfPathSpecFor(job, geo);
        const KerfPath check = offsetCutPath(
            kerfSpec, geo.sampleEqualArcLength(job.cut.knot_spacing_mm), plan.kerf_mm);
        // Planned on the edge then (the view shows it), but refused.
        if (!check.outcome.ok()) {
            kerfProblem = "kerf compensation: " + check.outcome.message;
            plan.kerf_mm = 0;
        }
    }

    // Pass 1: the cut points and, for the rotating method, the chuck angle that brings each
    // point to the top of the pipe (s0 x + c0 y = r, -c0 x + s0 y = 0), unwrapped.
    double previousChuck = deg2rad(job.cut.static_chuck_deg);
    for (size_t k = 0; k < plan.knots.size(); ++k) {
        PlannedPoint& p = plan.knots[k];
        p.t_s = plan.knot_dt_s * static_cast<double>(k);
        p.cut = geo.atArcLength(profile.distance(p.t_s));
        if (plan.kerf_mm > 0) offsetCutPoint(kerfSpec, p.cut, plan.kerf_mm);
        double chuck = deg2rad(job.cut.static_chuck_deg);
        if (spec.method == CutMethod::RotatingPipe) {
            chuck = std::atan2(p.cut.p_work.x(), p.cut.p_work.y());
            if (k > 0) chuck += 2 * kPi * std::round((previousChuck - chuck) / (2 * kPi));
        }
        previousChuck = chuck;
        p.chuck_rad = chuck;
    }
    if (spec.method == CutMethod::RotatingPipe) {
        // Shift the whole sweep by whole turns so that it fits the chuck's range, if it can.
        double lo = 1e300, hi = -1e300;
        for (const auto& p : plan.knots) {
            lo = std::min(lo, p.chuck_rad);
            hi = std::max(hi, p.chuck_rad);
        }
        const double mid = (robot.minRad(0) + robot.maxRad(0)) / 2;
        const double shift = 2 * kPi * std::round((mid - (lo + hi) / 2) / (2 * kPi));
        for (auto& p : plan.knots)
            p.chuck_rad += shift;
    }

    const double maxDev = job.cut.max_direction_deviation_deg;
    ArmVector previous = ArmVector::Zero();
    bool havePrevious = false;
    plan.reachable = true;
    std::vector<JointVector> q(plan.knots.size(), JointVector::Zero());
    for (size_t k = 0; k < plan.knots.size(); ++k) {
        if (options.cancel && options.cancel->load(std::memory_order_relaxed)) {
            plan.cancelled = true;
            plan.reachable = false;
            plan.problem = messageC("planning cancelled");
            return plan;
        }
        if (options.progress && k % 64 == 0)
            options.progress(static_cast<double>(k) / static_cast<double>(plan.knots.size()));
        PlannedPoint& p = plan.knots[k];
        const double chuck = p.chuck_rad;
        const Pose baseFromWork = robot.baseFromWork(chuck);
        p.tip_base = baseFromWork * p.cut.p_work;
        const Vec3 desired = baseFromWork.linear() * p.cut.approach_work;
        // Nearest torch axis in the plane of joint 1 (vertical, through Z0 and the tip).
        Vec3 planeNormal(-p.tip_base.y(), p.tip_base.x(), 0);
        Vec3 approach = desired;
        if (planeNormal.norm() > 1e-9) {
            planeNormal.normalize();
            approach = desired - desired.dot(planeNormal) * planeNormal;
            if (approach.norm() < 1e-9) approach = Vec3(0, 0, -1);
            approach.normalize();
        }
        p.approach_base = approach;
        // atan2 of the cross and dot products: exact near 0, where acos of a dot rounded to 1
        // is not (acos(1 - 1e-16) is 1.5e-8 rad of nothing).
        p.deviation_deg =
            rad2deg(std::atan2(desired.cross(approach).norm(), desired.dot(approach)));
        plan.max_deviation_deg = std::max(plan.max_deviation_deg, p.deviation_deg);

        p.ik = robot.solve(p.tip_base, approach, 0.0, havePrevious ? &previous : nullptr);
        if (p.ik.ok()) {
            previous = p.ik.q;
            havePrevious = true;
        }
        p.q[0] = chuck;
        p.q.segment<kArmJointCount>(1) = p.ik.ok() ? p.ik.q : previous;
        q[k] = p.q;

        if (plan.first_bad < 0) {
            std::string why;
            if (!robot.withinLimits(0, chuck)) {
                why = messageC("joint 0 (chuck) = %.3f deg is past its range [%.1f, %.1f] deg",
                               rad2deg(chuck), rad2deg(robot.minRad(0)), rad2deg(robot.maxRad(0)));
            } else if (!p.ik.ok()) {
                why = describe(p.ik);
            } else if (p.deviation_deg > maxDev + 1e-9) {
                why =
                    messageC("the torch must tilt %.2f deg into the plane of joint 1 (5-DOF arm), "
                             "more than cut.max_direction_deviation_deg = %.2f deg",
                             p.deviation_deg, maxDev);
            }
            if (!why.empty()) {
                plan.first_bad = static_cast<int>(k);
                plan.reachable = false;
                plan.problem = pointProblem(k, p, why);
            }
        }
    }
    plan.spline = JointSpline(std::move(q), plan.knot_dt_s);
    if (!kerfProblem.empty()) {
        plan.reachable = false;
        plan.problem = kerfProblem;
    }
    if (options.progress) options.progress(1.0);
    return plan;
}

} // namespace cutcell
