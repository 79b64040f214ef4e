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
    if (arm == "path") {
        Vec3 p, t;
        cell.pathTorch({deg2rad(q[0]), deg2rad(q[1]), deg2rad(q[2])}, p, t);
        *out = json::Object{{"arm", arm},
                            {"frame", "cell (x along the bar, z up), mm"},
                            {"tip_mm", vec(p)},
                            {"torch", vec(t)}};
        return Outcome::done();
    }
    // The groove arm: the whole torch frame (frame 5: x = the torch, z = joint 5's axis) in the
    // cell and in the arm's base frame {0}.
    const Pose base = cell.groove.forward(
        {deg2rad(q[0]), deg2rad(q[1]), deg2rad(q[2]), deg2rad(q[3]), deg2rad(q[4])});
    const Pose world = cell.groove_base * base;
    *out = json::Object{
        {"arm", arm},
        {"frame", "cell (x along the bar, z up), mm"},
        {"tip_mm", vec(world.translation())},
        {"torch", vec(world.linear().col(0))},
        {"x_axis", vec(world.linear().col(0))},
        {"y_axis", vec(world.linear().col(1))},
        {"z_axis", vec(world.linear().col(2))},
        {"base",
         json::Object{{"frame", "groove arm base {0} (modified DH: z along joint 1, links 1 and 2 "
                                "in its plane z = 0), mm"},
                      {"tip_mm", vec(base.translation())},
                      {"x_axis", vec(base.linear().col(0))},
                      {"y_axis", vec(base.linear().col(1))},
                      {"z_axis", vec(base.linear().col(2))}}}};
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
    // A position far beyond any cell (1e6 mm = 1 km) would overflow the frame change.
    constexpr double kMaxMm = 1e6;
    for (int i = 0; i < 3; ++i)
        if (!(std::fabs(p[i]) <= kMaxMm))
            return Outcome::refuse(formatC("--pose: %c = %g mm is outside [-%g, %g] mm", "xyz"[i],
                                           p[i], kMaxMm, kMaxMm));
    const double big = t.cwiseAbs().maxCoeff(); // scaled first: 1e300 components do not overflow
    if (!(big > 0) || !std::isfinite(big))
        return Outcome::refuse("--pose: the torch direction (tx, ty, tz) is zero or not finite");
    t /= big;
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
        *out = json::Object{
            {"arm", arm}, {"tip_mm", vec(p)}, {"torch", vec(t)}, {"branches", branches}};
        return Outcome::done();
    }
    // The groove arm: every solution, or why there is none (then the command exits 3, as for
    // an unreachable plan), or why the list is only a sample (a singular pose).
    const Vec3 pb = cell.groove_base.inverse() * p;
    const Vec3 tb = cell.groove_base.linear().transpose() * t;
    const GrooveTorchIk ik = cell.groove.solveTorch(pb, tb);
    for (const auto& b : ik.solutions)
        branches.push_back(branch(b.q, s->groove_limits));
    const char* status = ik.solutions.empty() ? "unreachable" : ik.continuum ? "singular" : "ok";
    json::Object o{{"arm", arm},
                   {"frame", "cell (x along the bar, z up), mm"},
                   {"tip_mm", vec(p)},
                   {"torch", vec(t)},
                   {"base_tip_mm", vec(pb)},
                   {"base_torch", vec(tb)},
                   {"status", std::string(status)}};
    if (!ik.why.empty()) o.emplace_back("reason", ik.why);
    o.emplace_back("branches", branches);
    *out = json::Value(std::move(o));
    if (ik.solutions.empty()) return Outcome::incomplete("groove arm: " + ik.why);
    return Outcome::done();
}

} // namespace cutcell
