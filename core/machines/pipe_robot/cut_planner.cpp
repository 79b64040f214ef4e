#include "core/machines/pipe_robot/cut_planner.h"
#include "core/common/c_format.h"
#include "core/machine/pipe_joint_section.h"
#include "core/process/kerf_offset.h"
#include "core/process/process_spec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace cutcell {

namespace {

// Why the point cannot be cut, and where it is.
std::string pointProblem(size_t index, const PlannedPoint& p, const std::string& why) {
    if (p.part != PathPart::Cut)
        return messageC("point %zu of the %s (x/y/z = %.2f/%.2f/%.2f mm): %s", index,
                        toString(p.part), p.cut.p_main.x(), p.cut.p_main.y(), p.cut.p_main.z(),
                        why.c_str());
    return messageC("point %zu (phi = %.2f deg, s = %.2f mm, x/y/z = %.2f/%.2f/%.2f mm): %s", index,
                    rad2deg(p.cut.phi_rad), p.cut.s_mm, p.cut.p_main.x(), p.cut.p_main.y(),
                    p.cut.p_main.z(), why.c_str());
}

// The time at which the profile has run `distance` (bisection: distance(t) is monotonic).
double timeAt(const SpeedProfile& profile, double distance) {
    double lo = 0, hi = profile.duration();
    for (int k = 0; k < 60; ++k) {
        const double mid = (lo + hi) / 2;
        (profile.distance(mid) < distance ? lo : hi) = mid;
    }
    return hi;
}

// The knots of a cut with leads, at equal time steps: the descent from the pierce height (from
// rest to rest at the cut speed), then the travel (lead-in, cut, overlap, lead-out) with the cut's
// ramps at its ends, knots about knot_spacing_mm apart at cutting speed.
void planLeadKnots(const Job& job, const RobotLeadPath& leads, CutPlan& plan) {
    const double v = job.cut.speed_mm_s;
    const SpeedProfile travel(leads.travelMm(), v, job.cut.ramp_s);
    const int intervals =
        std::max(16, static_cast<int>(std::ceil(leads.travelMm() / job.cut.knot_spacing_mm)));
    const double dt = travel.duration() / intervals;
    int descentIntervals = 0;
    double stretch = 1;
    std::optional<SpeedProfile> down;
    if (leads.descentMm() > 0) {
        down.emplace(leads.descentMm(), v, job.cut.ramp_s);
        descentIntervals = std::max(2, static_cast<int>(std::ceil(down->duration() / dt)));
        stretch = down->duration() / (dt * descentIntervals);
    }
    plan.knots.clear();
    plan.knots.resize(static_cast<size_t>(descentIntervals + intervals) + 1);
    for (int k = 0; k < descentIntervals; ++k) {
        PlannedPoint& p = plan.knots[static_cast<size_t>(k)];
        p.t_s = dt * k;
        p.part = PathPart::Descent;
        p.cut = leads.descentAt(down->distance(p.t_s * stretch));
    }
    const double t0 = dt * descentIntervals;
    for (int j = 0; j <= intervals; ++j) {
        PlannedPoint& p = plan.knots[static_cast<size_t>(descentIntervals + j)];
        p.t_s = t0 + dt * j;
        p.cut =
            leads.travelAt(j == intervals ? leads.travelMm() : travel.distance(dt * j), &p.part);
    }
    plan.knot_dt_s = dt;
    plan.cut_time_s = dt * (descentIntervals + intervals);
    const double ramp = travel.duration() - leads.travelMm() / v;
    plan.cruise_from_s = t0 + std::max(ramp, timeAt(travel, leads.leadInMm()));
    plan.cruise_to_s =
        t0 + std::min(travel.duration() - ramp, timeAt(travel, leads.leadInMm() + leads.cutMm()));
    plan.leads = true;
    plan.descent_mm = leads.descentMm();
    plan.lead_in_mm = leads.leadInMm();
    plan.overlap_mm = leads.overlapMm();
    plan.lead_out_mm = leads.leadOutMm();
    plan.pierce_height_mm = leads.settings().pierce_height_mm;
    plan.cut_height_mm = leads.settings().cut_height_mm;
    plan.pierce_delay_s = leads.settings().pierce_delay_s;
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

    {
        const double ramp = profile.duration() - plan.length_mm / job.cut.speed_mm_s;
        plan.cruise_from_s = ramp;
        plan.cruise_to_s = plan.cut_time_s - ramp;
    }

    // Leads: the knots of the whole program replace the cut's (a lead that cannot be made is
    // refused; the cut is planned without it then, as the view shows it).
    std::string leadProblem, leadKey;
    if (kerfProblem.empty() && robotLeadSettings(job).used) {
        const RobotLeadPath leads(job, geo, plan.kerf_mm > 0 ? kerfSpec : kerfPathSpecFor(job, geo),
                                  plan.kerf_mm);
        if (!leads.ok()) {
            leadProblem = leads.problem();
            leadKey = leads.problemKey();
        } else {
            planLeadKnots(job, leads, plan);
        }
    }

    Vec3 pierceSurface = Vec3::Zero(); // the first knot on the surface (leads)
    for (const PlannedPoint& p : plan.knots)
        if (p.part != PathPart::Descent) {
            pierceSurface = p.cut.p_work;
            break;
        }

    // Pass 1: the cut points and, for the rotating method, the chuck angle that brings each
    // point to the top of the pipe (s0 x + c0 y = r, -c0 x + s0 y = 0), unwrapped.
    double previousChuck = deg2rad(job.cut.static_chuck_deg);
    for (size_t k = 0; k < plan.knots.size(); ++k) {
        PlannedPoint& p = plan.knots[k];
        if (!plan.leads) {
            p.t_s = plan.knot_dt_s * static_cast<double>(k);
            p.cut = geo.atArcLength(profile.distance(p.t_s));
            if (plan.kerf_mm > 0) offsetCutPoint(kerfSpec, p.cut, plan.kerf_mm);
        }
        double chuck = deg2rad(job.cut.static_chuck_deg);
        if (spec.method == CutMethod::RotatingPipe) {
            // The descent keeps the chuck of the pierce point (a pure torch move on its axis).
            const Vec3& c = p.part == PathPart::Descent ? pierceSurface : p.cut.p_work;
            chuck = std::atan2(c.x(), c.y());
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
    if (!leadProblem.empty()) {
        plan.reachable = false;
        plan.problem = leadProblem;
        plan.problem_key = leadKey;
    }
    if (options.progress) options.progress(1.0);
    return plan;
}

} // namespace cutcell
