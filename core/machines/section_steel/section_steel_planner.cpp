#include "core/machines/section_steel/section_steel_planner.h"

#include "core/common/c_format.h"
#include "core/common/outcome.h"
#include "core/machines/section_steel/section_kerf.h"

#include <algorithm>
#include <cmath>

namespace cutcell::section_steel {
namespace {

const char* const kPathJointNames[3] = {"theta1", "theta2", "theta3"};
const char* const kGrooveJointNames[5] = {"theta1", "theta2", "theta3", "theta4", "theta5"};

template <size_t N> void unwrapTo(std::array<double, N>& q, const std::array<double, N>& ref) {
    for (size_t i = 0; i < N; ++i)
        q[i] = ref[i] + wrapAngle(q[i] - ref[i]);
}

template <size_t N>
double distance(const std::array<double, N>& a, const std::array<double, N>& b) {
    double s = 0;
    for (size_t i = 0; i < N; ++i)
        s += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(s);
}

// The first joint outside its limits ("" when all are inside).
template <size_t N>
std::string limitViolation(const std::array<double, N>& q, const std::array<ArmJointLimit, N>& lim,
                           const char* const* names, const char* arm) {
    for (size_t i = 0; i < N; ++i) {
        const double d = rad2deg(q[i]);
        if (d < lim[i].min_deg - 1e-9 || d > lim[i].max_deg + 1e-9)
            return messageC("%s joint %s = %.2f deg is outside its limits [%.1f, %.1f] deg", arm,
                            names[i], d, lim[i].min_deg, lim[i].max_deg);
    }
    return {};
}

// Picks among IK solutions: inside the limits, nearest to ref (unwrapped to it). Refused with
// why when none fits.
template <size_t N>
Outcome pick(std::vector<std::array<double, N>> sols, const std::array<double, N>& ref,
             const std::array<ArmJointLimit, N>& lim, const char* const* names, const char* arm,
             std::array<double, N>& out, bool unwrap = true) {
    if (sols.empty())
        return Outcome::refuse(messageC("%s: no inverse-kinematics solution (out of reach)", arm));
    double best = 1e300;
    std::string firstViolation;
    for (auto& q : sols) {
        // From a rest position (the first point) the joints take their principal values; along
        // the path they stay continuous (wrist joints may turn past +-180 deg).
        if (unwrap) unwrapTo(q, ref);
        const std::string v = limitViolation(q, lim, names, arm);
        if (!v.empty()) {
            if (firstViolation.empty()) firstViolation = v;
            continue;
        }
        const double d = distance(q, ref);
        if (d < best) {
            best = d;
            out = q;
        }
    }
    if (best < 1e300) return Outcome::done();
    return Outcome::refuse(messageC("%s (all %zu branches)", firstViolation.c_str(), sols.size()));
}

// The groove arm's branch at the first point of a pass: of the IK branches inside the limits
// the one it can follow furthest along the pass (Gauss-Newton from point to point, inside the
// limits, no jumps); near the park position on a tie. False when no branch is inside limits.
bool grooveStartBranch(const SteelCell& cell, const SectionSteelSpec& spec, const CutPass& pass,
                       const Q5& park, double jump, Q5& out) {
    const Vec3 p0 = cell.groove_base.inverse() * pass.samples.front().p;
    const Vec3 t0 = cell.groove_base.linear().transpose() * pass.samples.front().t;
    size_t bestReach = 0;
    double bestDistance = 1e300;
    bool found = false;
    for (const auto& s : cell.groove.inverseTorch(p0, t0)) {
        if (!limitViolation(s.q, spec.groove_limits, kGrooveJointNames, "").empty()) continue;
        Q5 q = s.q;
        size_t reach = 1;
        for (; reach < pass.samples.size(); ++reach) {
            const TorchTarget& tt = pass.samples[reach];
            Q5 next = q;
            if (!cell.groove.trackTorch(cell.groove_base.inverse() * tt.p,
                                        cell.groove_base.linear().transpose() * tt.t, next))
                break;
            unwrapTo(next, q);
            if (distance(next, q) > jump ||
                !limitViolation(next, spec.groove_limits, kGrooveJointNames, "").empty())
                break;
            q = next;
        }
        const double d = distance(s.q, park);
        if (!found || reach > bestReach || (reach == bestReach && d < bestDistance)) {
            found = true;
            bestReach = reach;
            bestDistance = d;
            out = s.q;
        }
    }
    return found;
}

} // namespace

SteelCell::SteelCell(const SectionSteelSpec& s) : SteelCell(s, 0.0) {}

SteelCell::SteelCell(const SectionSteelSpec& s, double kerf_mm)
    : path(s.path_links_mm[0], s.path_links_mm[1], s.path_links_mm[2]) {
    path_base_y = s.path_base_y_mm;
    path_base_z = s.path_base_z_mm;
    // The mitre frame: both arms stand on it; it turns x onto the cut plane's normal about
    // the section's centre (0, 0, h/2), the identity for a square cut.
    const Vec3 m = EndCut(s).planeNormal();
    const Vec3 u1 = (Vec3::UnitY() - Vec3::UnitY().dot(m) * m).normalized();
    Pose mitre = Pose::Identity();
    mitre.linear().col(0) = m;
    mitre.linear().col(1) = u1;
    mitre.linear().col(2) = m.cross(u1);
    const Vec3 centre(0, 0, s.section.h_mm / 2);
    mitre.translation() = centre - mitre.linear() * centre;
    path_frame = mitre;
    path_frame.translation() = mitre * Vec3(0, path_base_y, path_base_z);
    Pose square = Pose::Identity();
    Eigen::Matrix3d R;
    R.col(0) = Vec3(0, 0, -1);
    R.col(1) = Vec3(0, -1, 0);
    R.col(2) = Vec3(-1, 0, 0);
    square.linear() = R;
    square.translation() = Vec3(s.groove_base_x_mm, s.groove_base_y_mm, s.groove_base_z_mm);
    groove_base = mitre * square;
    // Kerf compensation: the frame along the bar (none at k = 0: the poses stay bit for bit).
    if (kerf_mm != 0) {
        frame_shift_mm = squarePassShiftMm(EndCut(s), kerf_mm);
        path_frame.translation().x() += frame_shift_mm;
        groove_base.translation().x() += frame_shift_mm;
    }
}

void SteelCell::pathTorch(const std::array<double, 3>& q, Vec3& p, Vec3& t) const {
    const PlanarPose pp = path.forward(q);
    p = path_frame * Vec3(0, pp.x_mm, pp.y_mm);
    t = path_frame.linear() * Vec3(0, std::cos(pp.phi_rad), std::sin(pp.phi_rad));
}

bool SteelCell::pathPlanar(const Vec3& p, const Vec3& t, PlanarPose& out) const {
    const Vec3 pl = path_frame.inverse() * p, tl = path_frame.linear().transpose() * t;
    out = PlanarPose{pl.y(), pl.z(), std::atan2(tl.z(), tl.y())};
    return std::fabs(pl.x()) < 1e-6 && std::fabs(tl.x()) < 1e-9;
}

void SteelCell::grooveTorch(const Q5& q, Vec3& p, Vec3& t) const {
    const Pose T = groove_base * groove.forward(q);
    p = T.translation();
    t = T.linear().col(0);
}

// Why point k of the pass cannot be cut, and where it is.
std::string pointProblem(const EndCut& cut, const CutPass& pass, size_t k, const std::string& why) {
    const TorchTarget& t = pass.samples[k];
    const char* segment = cut.outline().segments()[t.segment].name.c_str();
    if (t.lead != kLeadNone)
        return messageC("point %zu of pass %s (the %s at %s): %s", k, pass.name.c_str(),
                        t.lead == kLeadPierce ? messageC("pierce").c_str()
                        : t.lead == kLeadIn   ? messageC("lead-in").c_str()
                                              : messageC("lead-out").c_str(),
                        segment, why.c_str());
    if (t.turning)
        return messageC("point %zu of pass %s (%s, turning at the corner, s = %.1f mm): %s", k,
                        pass.name.c_str(), segment, t.s_mm, why.c_str());
    return messageC("point %zu of pass %s (%s, s = %.1f mm): %s", k, pass.name.c_str(), segment,
                    t.s_mm, why.c_str());
}

SteelPlan planEndCut(const SectionSteelSpec& spec) {
    return planEndCut(spec, 0.0);
}

std::string steelPathPointProblem(const SteelCell& cell, const SectionSteelSpec& spec,
                                  const EndCut& cut, const TorchTarget& tt) {
    PlanarPose pose;
    if (!cell.pathPlanar(tt.p, tt.t, pose))
        return messageC("the point x = %.1f, y = %.1f, z = %.1f mm is off the path arm's plane "
                        "(a planar 3R arm in the cut plane)",
                        tt.p.x(), tt.p.y(), tt.p.z());
    std::vector<std::array<double, 3>> sols;
    for (const auto& s : cell.path.inverse(pose))
        sols.push_back(s.q);
    std::array<double, 3> q{};
    const std::array<double, 3> ref{deg2rad(spec.park_deg[0]), deg2rad(spec.park_deg[1]),
                                    deg2rad(spec.park_deg[2])};
    if (const Outcome o = pick(sols, ref, spec.path_limits, kPathJointNames,
                               messageC("path arm").c_str(), q, false);
        !o.ok())
        return o.message;
    if (const auto hit = torchHit(cut, cut.torchBody(), tt.p, tt.t, true))
        return messageC("the torch body hits the section %.0f mm behind the tip at x = %.1f, y = "
                        "%.1f, z = %.1f mm (torch_length_mm = %.0f, torch_radius_mm = %.0f)",
                        hit->behind_mm, hit->at.x(), hit->at.y(), hit->at.z(), spec.torch_length_mm,
                        spec.torch_radius_mm);
    return {};
}

namespace {

// The first lead sample (of the lead-in and pierce: before, or the lead-out: after) the path arm
// cannot cut, and why; "" when all fit.
std::string leadSamplesProblem(const SteelCell& cell, const SectionSteelSpec& spec,
                               const EndCut& cut, const std::vector<TorchTarget>& samples) {
    for (const TorchTarget& t : samples)
        if (std::string why = steelPathPointProblem(cell, spec, cut, t); !why.empty())
            return messageC("at x = %.1f, y = %.1f, z = %.1f mm: %s", t.p.x(), t.p.y(), t.p.z(),
                            why.c_str());
    return {};
}

// The leads of the square pass, checked point by point; a lead that does not fit is refused
// with the longest length that does (bisection: a shorter lead stays nearer the cut's end).
void addLeads(SteelPlan& plan, const SteelCell& cell, const SectionSteelSpec& spec,
              const EndCut& cut, const SteelLeadSpec& leads) {
    if (!leads.used() || plan.passes.empty() || plan.passes.front().name != "square") return;
    CutPass& square = plan.passes.front();
    for (const bool in : {true, false}) {
        const LeadSpec& lead = in ? leads.in : leads.out;
        if (!lead.used()) continue;
        auto problemAt = [&](double L) {
            SteelLeadSpec one = leads;
            (in ? one.in : one.out).length_mm = L;
            const SteelLeadSamples s = steelLeadSamples(spec, square, one, plan.dt);
            return leadSamplesProblem(cell, spec, cut, in ? s.before : s.after);
        };
        const std::string why = problemAt(lead.length_mm);
        if (why.empty()) continue;
        double lo = 0, hi = lead.length_mm;
        for (int k = 0; k < 30; ++k) {
            const double mid = (lo + hi) / 2;
            (problemAt(mid).empty() ? lo : hi) = mid;
        }
        const char* key = in ? "lead_in" : "lead_out";
        plan.lead_key = std::string("process.") + key + ".length_mm";
        plan.lead_problem = messageC(
            "process.%s.length_mm = %.6g mm is too long for the section-steel cutter: the %s "
            "(%s, off the free edge in the path arm's plane) cannot be cut %s; the longest that "
            "fits is %.3f mm",
            key, lead.length_mm, (in ? messageC("lead-in") : messageC("lead-out")).c_str(),
            toString(lead.kind), why.c_str(), std::floor(lo * 1000) / 1000);
        return;
    }
    plan.leads = steelLeadSamples(spec, square, leads, plan.dt);
    addSteelLeads(square, plan.leads);
    plan.leads_added = true;
}

} // namespace

SteelPlan planEndCut(const SectionSteelSpec& spec, double kerf_mm) {
    return planEndCut(spec, kerf_mm, SteelLeadSpec{});
}

SteelPlan planEndCut(const SectionSteelSpec& spec, double kerf_mm, const SteelLeadSpec& leads) {
    SteelPlan plan;
    const EndCut cut(spec);
    plan.dt = spec.knot_spacing_mm / spec.speed_mm_s;
    plan.passes = cut.passes(plan.dt);
    // Kerf compensation: every target moves to the torch centre, the arms' frame with the square
    // pass's plane. Refused: planned on the edge (the view shows it), the plan refused.
    if (kerf_mm != 0) {
        if (const Outcome o = compensateSteelKerf(cut, plan.passes, kerf_mm); o.ok())
            plan.kerf_mm = kerf_mm;
        else
            plan.kerf_problem = "kerf compensation: " + o.message;
    }
    const SteelCell cell(spec, plan.kerf_mm);
    plan.frame_shift_mm = cell.frame_shift_mm;
    if (plan.kerf_problem.empty()) addLeads(plan, cell, spec, cut, leads);
    plan.problem = plan.kerf_problem.empty() ? plan.lead_problem : plan.kerf_problem;
    JointVector park = JointVector::Zero();
    for (int i = 0; i < kSteelAxes; ++i)
        park[i] = deg2rad(spec.park_deg[static_cast<size_t>(i)]);
    auto fail = [&](const std::string& msg) {
        if (plan.problem.empty()) plan.problem = msg;
        ++plan.failed_points;
    };
    JointVector cur = park;
    // Larger joint steps than this between two points are a change of IK branch: the torch
    // turns at most reorient_deg_s at a corner, the tip moves knot_spacing_mm.
    const double jump = 0.3 + 2 * plan.dt * deg2rad(spec.reorient_deg_s);
    for (size_t pi = 0; pi < plan.passes.size(); ++pi) {
        const CutPass& pass = plan.passes[pi];
        std::vector<JointVector> knots;
        std::array<double, 3> qp{park[0], park[1], park[2]};
        Q5 qg{park[3], park[4], park[5], park[6], park[7]};
        bool first = true;
        for (size_t k = 0; k < pass.samples.size(); ++k) {
            const TorchTarget& tt = pass.samples[k];
            Outcome picked; // the IK branch of this point
            // Torch body (cylinder behind the tip) against the section.
            if (const auto hit = torchHit(cut, cut.torchBody(), tt.p, tt.t, pass.name == "square"))
                fail(pointProblem(
                    cut, pass, k,
                    messageC("the torch body hits the section %.0f mm behind the tip at x = %.1f, "
                             "y = %.1f, z = %.1f mm (torch_length_mm = %.0f, torch_radius_mm = "
                             "%.0f, lean %.0f deg of max_lean_deg = %.0f)",
                             hit->behind_mm, hit->at.x(), hit->at.y(), hit->at.z(),
                             spec.torch_length_mm, spec.torch_radius_mm, rad2deg(tt.lean_rad),
                             spec.max_lean_deg)));
            Vec3 p, t;
            if (!pass.groove_arm) {
                PlanarPose pose;
                cell.pathPlanar(tt.p, tt.t, pose); // the square / mitre pass lies in its plane
                std::vector<std::array<double, 3>> sols;
                for (const auto& s : cell.path.inverse(pose))
                    sols.push_back(s.q);
                std::array<double, 3> q{};
                picked = pick(sols, qp, spec.path_limits, kPathJointNames,
                              messageC("path arm").c_str(), q, !first);
                if (!picked.ok()) {
                    fail(pointProblem(cut, pass, k, picked.message));
                } else {
                    if (!first && distance(q, qp) > jump)
                        fail(pointProblem(cut, pass, k,
                                          messageC("path arm changes branch (joint jump %.1f deg)",
                                                   rad2deg(distance(q, qp)))));
                    qp = q;
                }
                cell.pathTorch(qp, p, t);
            } else {
                const Vec3 pb = cell.groove_base.inverse() * tt.p;
                const Vec3 tb = cell.groove_base.linear().transpose() * tt.t;
                Q5 q = qg;
                bool ok = !first && cell.groove.trackTorch(pb, tb, q);
                if (first) {
                    const Q5 park5{park[3], park[4], park[5], park[6], park[7]};
                    ok = grooveStartBranch(cell, spec, pass, park5, jump, q);
                }
                if (ok && !first) {
                    unwrapTo(q, qg);
                    ok = limitViolation(q, spec.groove_limits, kGrooveJointNames, "").empty() &&
                         distance(q, qg) < jump;
                }
                if (!ok) {
                    std::vector<Q5> sols;
                    for (const auto& s : cell.groove.inverseTorch(pb, tb))
                        sols.push_back(s.q);
                    picked = pick(sols, qg, spec.groove_limits, kGrooveJointNames,
                                  messageC("groove arm").c_str(), q, !first);
                    if (!picked.ok()) {
                        fail(pointProblem(cut, pass, k, picked.message));
                        q = qg;
                    } else if (!first && distance(q, qg) > jump) {
                        fail(
                            pointProblem(cut, pass, k,
                                         messageC("groove arm changes branch (joint jump %.1f deg)",
                                                  rad2deg(distance(q, qg)))));
                    }
                }
                qg = q;
                cell.grooveTorch(qg, p, t);
            }
            if (picked.ok())
                plan.max_torch_error_mm = std::max(plan.max_torch_error_mm, (p - tt.p).norm());
            first = false;
            JointVector j = JointVector::Zero();
            for (int i = 0; i < 3; ++i)
                j[i] = qp[static_cast<size_t>(i)];
            for (int i = 0; i < 5; ++i)
                j[3 + i] = qg[static_cast<size_t>(i)];
            knots.push_back(j);
        }
        // Transition from the previous pass (joint move, cosine blend, <= 30 deg/s).
        if (!plan.knots.empty() && !knots.empty()) {
            const JointVector from = cur, to = knots.front();
            const double span = (to - from).cwiseAbs().maxCoeff();
            const double T = std::max(2.0, span / deg2rad(30.0));
            const size_t n = static_cast<size_t>(std::ceil(T / plan.dt));
            for (size_t k = 1; k < n; ++k) {
                const double f =
                    0.5 - 0.5 * std::cos(kPi * static_cast<double>(k) / static_cast<double>(n));
                plan.knots.push_back(from + f * (to - from));
                plan.info.push_back({-1, k});
            }
        }
        for (size_t k = 0; k < knots.size(); ++k) {
            plan.knots.push_back(knots[k]);
            plan.info.push_back({static_cast<int>(pi), k});
        }
        if (!knots.empty()) cur = knots.back();
        plan.length_mm += pass.length_mm;
    }
    plan.ok = plan.failed_points == 0 && plan.knots.size() >= 2 && plan.kerf_problem.empty() &&
              plan.lead_problem.empty();
    if (plan.knots.size() < 2 && plan.problem.empty()) {
        plan.problem = setupTwoProblem(spec);
        if (plan.problem.empty()) plan.problem = messageC("the cut has no path");
    }
    if (plan.ok) {
        plan.spline = JointSpline(plan.knots, plan.dt);
        plan.cut_time_s = plan.spline.duration();
    } else if (plan.knots.size() >= 2) {
        // Refused: the time the cut would take (the summary), knots dt apart as the spline's.
        plan.cut_time_s = plan.dt * static_cast<double>(plan.knots.size() - 1);
    }
    return plan;
}

} // namespace cutcell::section_steel
