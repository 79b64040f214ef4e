#include "core/machines/pipe_robot/pipe_robot_program.h"

#include "core/common/c_format.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"
#include "core/machines/pipe_robot/robot_torch_height.h"

#include "core/job/job_io.h"
#include "core/json/json.h"

#include <cstdio>

namespace cutcell {

Vec3 PipeRobotTipModel::tip(const JointVector& q) const {
    // The same expression as TrackingStats' pipe-robot path, so figures agree bit for bit.
    return robot_.tip(q.segment<kArmJointCount>(1));
}

void PipeRobotTipModel::tipPair(const JointVector& qa, const JointVector& qb, Vec3& a,
                                Vec3& b) const {
    robot_.tipPair(qa.segment<kArmJointCount>(1), qb.segment<kArmJointCount>(1), a, b);
}

Vec3 PipeRobotTipModel::tipOnWork(const JointVector& q, const Vec3& tipBase) const {
    return robot_.workFromBase(q[0], tipBase);
}

std::shared_ptr<const MotionProgram> buildPipeRobotProgram(const Job& job, const CutPlan& plan,
                                                           const std::string& jobText) {
    if (!plan.reachable) throw std::invalid_argument("the cut is not reachable: " + plan.problem);
    if (plan.spline.empty()) throw std::invalid_argument("the plan has no trajectory");
    const PipeRobotSpec& spec = pipeRobotSpec(job);
    auto p = std::make_shared<MotionProgram>();
    p->machine = kPipeRobotId;
    p->method = toString(spec.method);
    p->axis_count = kAxisCount;
    p->axis_names = {"chuck (theta0)", "theta1", "theta2", "theta3", "theta4", "theta5"};
    p->axis_linear.fill(false);
    p->spline = plan.spline;
    p->cut_time_s = plan.cut_time_s;
    p->length_mm = plan.length_mm;
    p->point_count = plan.knots.size();
    p->reference = JointVector::Zero();
    for (int i = 0; i < kAxisCount; ++i) {
        const DhRow& r = spec.dh[static_cast<size_t>(i)];
        p->min_position[i] = deg2rad(r.min_deg);
        p->max_position[i] = deg2rad(r.max_deg);
        if (p->reference[i] < p->min_position[i] || p->reference[i] > p->max_position[i]) {
            char buf[200];
            snprintfC(buf, sizeof buf,
                      "reference of axis %d (%s) = %.3f deg is outside its range %.3f .. %.3f deg",
                      i, p->axis_names[static_cast<size_t>(i)].c_str(), rad2deg(p->reference[i]),
                      r.min_deg, r.max_deg);
            throw std::invalid_argument(buf);
        }
    }
    p->tip_model = std::make_shared<PipeRobotTipModel>(spec.dh);
    if (const RobotTorchHeightSetup thc = robotTorchHeightSetup(job); thc.used) {
        if (!thc.problem.empty()) throw std::invalid_argument(thc.problem);
        p->correction = std::make_shared<RobotTorchHeight>(PipeRobot(spec.dh), thc);
        p->sensors_used |= 1u << kArcVoltageSensor; // the arc voltage
    }
    p->min_run_s = job.sim.duration_s;
    // The same window as simulateCut(): the cosine ramps at both ends (and leads) are excluded.
    p->cruise_from_s = plan.cruise_from_s;
    p->cruise_to_s = plan.cruise_to_s;
    // Leads: the torch is lit at the pierce (the first knot, at the pierce height) and pierces
    // there before the descent; without leads the chart's delay was never applied (kept so).
    if (plan.leads) p->pierce_s = plan.pierce_delay_s;
    p->name = job.name;
    p->source_text = jobText.empty() ? json::write(jobToJson(job)) : jobText;
    return p;
}

} // namespace cutcell
