#include "core/machines/section_steel/section_steel_program.h"

#include "core/common/c_format.h"
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/machines/section_steel/section_steel_module.h"

#include <cmath>
#include <stdexcept>

namespace cutcell::section_steel {

Vec3 SteelTipModel::tip(const JointVector& q) const {
    // The arm that has left its park position carries the cutting torch.
    const double pathMoved = (q.head<3>() - park_.head<3>()).cwiseAbs().maxCoeff();
    const double grooveMoved = (q.segment<5>(3) - park_.segment<5>(3)).cwiseAbs().maxCoeff();
    Vec3 p, t;
    if (pathMoved >= grooveMoved)
        cell_.pathTorch({q[0], q[1], q[2]}, p, t);
    else
        cell_.grooveTorch({q[3], q[4], q[5], q[6], q[7]}, p, t);
    return p;
}

std::shared_ptr<const MotionProgram> buildSectionSteelProgram(const Job& job,
                                                              const SectionSteelSpec& spec,
                                                              const SteelPlan& plan,
                                                              const std::string& jobText) {
    if (!plan.ok) throw std::invalid_argument("the cut is not feasible: " + plan.problem);
    auto p = std::make_shared<MotionProgram>();
    p->machine = kSectionSteelId;
    p->method = plan.passes.size() > 1 ? "square + groove" : "square";
    p->axis_count = kSteelAxes;
    const char* names[kSteelAxes] = {"path theta1",   "path theta2",   "path theta3",
                                     "groove theta1", "groove theta2", "groove theta3",
                                     "groove theta4", "groove theta5"};
    for (int i = 0; i < kSteelAxes; ++i) {
        p->axis_names[static_cast<size_t>(i)] = names[i];
        p->axis_linear[static_cast<size_t>(i)] = false;
        p->axis_modes[static_cast<size_t>(i)] = AxisCommandMode::Position;
    }
    p->source_kind = MotionSourceKind::JointSpline;
    p->spline = plan.spline;
    p->cut_time_s = plan.cut_time_s;
    p->length_mm = plan.length_mm;
    p->point_count = plan.knots.size();
    JointVector park = JointVector::Zero();
    for (int i = 0; i < kSteelAxes; ++i)
        park[i] = deg2rad(spec.park_deg[static_cast<size_t>(i)]);
    p->reference = park;
    for (size_t i = 0; i < 3; ++i) {
        p->min_position[static_cast<int>(i)] = deg2rad(spec.path_limits[i].min_deg);
        p->max_position[static_cast<int>(i)] = deg2rad(spec.path_limits[i].max_deg);
    }
    for (size_t i = 0; i < 5; ++i) {
        p->min_position[static_cast<int>(3 + i)] = deg2rad(spec.groove_limits[i].min_deg);
        p->max_position[static_cast<int>(3 + i)] = deg2rad(spec.groove_limits[i].max_deg);
    }
    p->tip_model = std::make_shared<SteelTipModel>(spec, park, plan.kerf_mm);
    p->min_run_s = job.sim.duration_s;
    p->cruise_from_s = spec.ramp_s + (plan.leads_added ? plan.leads.before_s : 0.0);
    p->cruise_to_s = plan.cut_time_s - spec.ramp_s;
    p->name = job.name;
    p->source_text = jobText.empty() ? json::write(jobToJson(job)) : jobText;
    return p;
}

std::string steelPathCsv(const SectionSteelSpec& spec, const SteelPlan& plan) {
    const EndCut cut(spec);
    std::string out = "pass,point,face,s_mm,x_mm,y_mm,z_mm,tx,ty,tz,tilt_deg";
    const char* names[kSteelAxes] = {"path_q1_deg",   "path_q2_deg",   "path_q3_deg",
                                     "groove_q1_deg", "groove_q2_deg", "groove_q3_deg",
                                     "groove_q4_deg", "groove_q5_deg"};
    for (const char* n : names)
        out += std::string(",") + n;
    const bool kerf = plan.kerf_mm > 0;
    if (kerf) out += ",edge_x_mm,edge_y_mm,edge_z_mm";
    out += "\n";
    for (size_t k = 0; k < plan.knots.size(); ++k) {
        const KnotInfo& info = plan.info[k];
        if (info.pass < 0) continue;
        const CutPass& pass = plan.passes[static_cast<size_t>(info.pass)];
        const TorchTarget& t = pass.samples[info.sample];
        // Names hold commas ("top flange, upper face"): ';' in the CSV's text columns.
        std::string face = cut.outline().segments()[t.segment].name, passName = pass.name;
        if (t.lead != kLeadNone)
            face = std::string(t.lead == kLeadPierce ? "pierce"
                               : t.lead == kLeadIn   ? "lead-in"
                                                     : "lead-out") +
                   " (" + face + ")";
        for (std::string* text : {&face, &passName})
            for (char& c : *text)
                if (c == ',') c = ';';
        out += formatC("%s,%zu,%s,%.4f,%.4f,%.4f,%.4f,%.6f,%.6f,%.6f,%.4f", passName.c_str(),
                       info.sample, face.c_str(), t.s_mm, t.p.x(), t.p.y(), t.p.z(), t.t.x(),
                       t.t.y(), t.t.z(), rad2deg(t.tilt_rad));
        for (int i = 0; i < kSteelAxes; ++i)
            out += formatC(",%.6f", rad2deg(plan.knots[k][i]));
        if (kerf) out += formatC(",%.4f,%.4f,%.4f", t.edge_p.x(), t.edge_p.y(), t.edge_p.z());
        out += "\n";
    }
    return out;
}

} // namespace cutcell::section_steel
