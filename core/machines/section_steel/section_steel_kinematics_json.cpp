// `cutcell-cli fk` / `ik` for the section-steel cell: arm "path" (3 joints) or "groove" (5).
#include "core/common/c_format.h"
#include "core/machines/section_steel/section_steel_module.h"
#include "core/machines/section_steel/section_steel_planner.h"

#include <cmath>

namespace cutcell {

using namespace section_steel;

namespace {

json::Value vec(const Vec3& v) {
    return json::Array{v.x(), v.y(), v.z()};
}

template <size_t N>
json::Value branch(const std::array<double, N>& q, const std::array<ArmJointLimit, N>& lim) {
    json::Array joints;
    std::string status = "ok";
    for (size_t i = 0; i < N; ++i) {
        const double d = rad2deg(q[i]);
        joints.emplace_back(d);
        if (status == "ok" && (d < lim[i].min_deg || d > lim[i].max_deg))
            status = formatC("joint theta%zu = %.3f deg is outside its limits [%.1f, %.1f] deg",
                             i + 1, d, lim[i].min_deg, lim[i].max_deg);
    }
    return json::Object{{"joints_deg", joints}, {"status", status}};
}

Outcome checkArm(const std::string& arm) {
    if (arm == "path" || arm == "groove") return Outcome::done();
    return Outcome::refuse("--arm = " + json::quote(arm) + " is not one of \"path\", \"groove\"");
}

} // namespace

Outcome SectionSteelModule::forwardKinematics(const Job& job, const std::string& arm,
                                              const std::vector<double>& q,
                                              json::Value* out) const {
    if (Outcome o = checkArm(arm); !o.ok()) return o;
    const SectionSteelSpec* s = job.machine_spec.as<SectionSteelSpec>();
    const size_t n = arm == "path" ? 3 : 5;
    if (!s || q.size() != n)
        return Outcome::refuse("--joints needs " + std::to_string(n) + " values (deg) for the " +
                               arm + " arm, found " + std::to_string(q.size()));
    const SteelCell cell(*s);
    Vec3 p, t;
    if (arm == "path")
        cell.pathTorch({deg2rad(q[0]), deg2rad(q[1]), deg2rad(q[2])}, p, t);
    else
        cell.grooveTorch(
            {deg2rad(q[0]), deg2rad(q[1]), deg2rad(q[2]), deg2rad(q[3]), deg2rad(q[4])}, p, t);
    *out = json::Object{{"arm", arm},
                        {"frame", "cell (x along the bar, z up), mm"},
                        {"tip_mm", vec(p)},
                        {"torch", vec(t)}};
    return Outcome::done();
}

Outcome SectionSteelModule::inverseKinematics(const Job& job, const std::string& arm,
                                              const std::vector<double>& pose,
                                              json::Value* out) const {
    if (Outcome o = checkArm(arm); !o.ok()) return o;
    const SectionSteelSpec* s = job.machine_spec.as<SectionSteelSpec>();
    if (!s || pose.size() != 6)
        return Outcome::refuse("--pose needs 6 values: x, y, z (mm), tx, ty, tz (torch direction)");
    const Vec3 p(pose[0], pose[1], pose[2]);
    Vec3 t(pose[3], pose[4], pose[5]);
    if (!(t.norm() > 1e-9))
        return Outcome::refuse("--pose: the torch direction (tx, ty, tz) is zero");
    t.normalize();
    const SteelCell cell(*s);
    json::Array branches;
    if (arm == "path") {
        PlanarPose pp;
        if (!cell.pathPlanar(p, t, pp))
            return Outcome::refuse("--pose: the path arm works in the cut plane (square: x = 0 "
                                   "and tx = 0; mitred: the mitre plane of end_cut)");
        for (const auto& b : cell.path.inverse(pp))
            branches.push_back(branch(b.q, s->path_limits));
    } else {
        const Vec3 pb = cell.groove_base.inverse() * p;
        const Vec3 tb = cell.groove_base.linear().transpose() * t;
        for (const auto& b : cell.groove.inverseTorch(pb, tb))
            branches.push_back(branch(b.q, s->groove_limits));
    }
    *out =
        json::Object{{"arm", arm}, {"tip_mm", vec(p)}, {"torch", vec(t)}, {"branches", branches}};
    return Outcome::done();
}

} // namespace cutcell
