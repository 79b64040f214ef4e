// Lead-in / lead-out and pierce height of the section-steel end cut (section_lead.h): the
// properties, over random sections, mitres and kerfs, recomputed from the cut plane, the
// outline and the arms' forward kinematics rather than from the lead code.
#include "core/common/c_format.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/machines/section_steel/section_kerf.h"
#include "core/machines/section_steel/section_lead.h"
#include "core/machines/section_steel/section_steel_module.h"
#include "core/machines/section_steel/section_steel_planner.h"
#include "core/machines/section_steel/section_steel_program.h"
#include "core/process/process_spec.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace cutcell;
using namespace cutcell::section_steel;

namespace {

// A random setup-1 end cut of a catalogue section, mitres inside the validated ranges, no
// grooves (the leads belong to the square pass; grooves only add passes after it).
SectionSteelSpec randomSpec(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    const auto& catalogue = sectionCatalogue();
    SectionSteelSpec s = defaultSectionSteelSpec();
    s.section = catalogue[static_cast<size_t>(u(rng) * static_cast<double>(catalogue.size())) %
                          catalogue.size()];
    s.cut.mitre_vertical_deg = u(rng) < 0.3 ? 0 : 60 * u(rng) - 30;
    s.cut.mitre_horizontal_deg = u(rng) < 0.3 ? 0 : 60 * u(rng) - 30;
    return s;
}

SteelLeadSpec leadsOf(LeadKind in, double inL, LeadKind out, double outL) {
    SteelLeadSpec l;
    l.in.kind = in;
    l.in.length_mm = inL;
    l.out.kind = out;
    l.out.length_mm = outL;
    l.pierce_height_mm = 3.8;
    l.cut_height_mm = 1.5;
    return l;
}

// The square pass with the kerf compensated, as planEndCut makes it.
CutPass squarePass(const SectionSteelSpec& s, double kerf) {
    const EndCut cut(s);
    std::vector<CutPass> passes = cut.passes(s.knot_spacing_mm / s.speed_mm_s);
    EXPECT_TRUE(compensateSteelKerf(cut, passes, kerf).ok());
    return passes.front();
}

// Signed distance from the theoretical cut plane (through the edge point e, normal m toward the
// off-cut), computed from the mitres (section_steel_spec.h).
double acrossCut(const SectionSteelSpec& s, const Vec3& p, const Vec3& edgePoint) {
    const Vec3 m = Vec3(1, -std::tan(deg2rad(s.cut.mitre_vertical_deg)),
                        -std::tan(deg2rad(s.cut.mitre_horizontal_deg)))
                       .normalized();
    return (p - edgePoint).dot(m);
}

Job plasmaSteelJob() {
    Job job = findMachine(kSectionSteelId)->defaultJob();
    job.process.used = true;
    job.process.process = CutProcess::Plasma;
    job.process.material = "mild_steel";
    job.process.consumable = "Powermax65/85 65A shielded";
    job.process.override.set(CutFigure::KerfMm, 1.6);
    return job;
}

std::vector<std::string> issueKeys(const Job& job) {
    std::vector<std::string> keys;
    for (const auto& i : findMachine(kSectionSteelId)->validate(job))
        keys.push_back(i.key);
    return keys;
}

bool hasKey(const std::vector<std::string>& keys, const std::string& k) {
    return std::find(keys.begin(), keys.end(), k) != keys.end();
}

} // namespace

// Every lead point (the polyline and every sample of the pierce, lead-in and lead-out) lies in
// the path arm's plane, k/2 across the cut surface on the scrap side (so at least k/2 from the
// part's edge), off the material; a line lead lies in the start (end) face's plane too.
TEST(SectionSteelLead, LeadPointsOnTheScrapSideOffTheMaterialOverRandomSections) {
    std::mt19937 rng(4711);
    std::uniform_real_distribution<double> u(0, 1);
    double worstPlane = 0, worstFace = 0, minAcrossMinusHalfKerf = 1e9;
    size_t points = 0;
    for (int trial = 0; trial < 24; ++trial) {
        const SectionSteelSpec s = randomSpec(rng);
        const double kerf = 2.5 * u(rng);
        const LeadKind kin = u(rng) < 0.5 ? LeadKind::Line : LeadKind::Arc;
        const LeadKind kout = u(rng) < 0.5 ? LeadKind::Line : LeadKind::Arc;
        const SteelLeadSpec leads = leadsOf(kin, 0.5 + 30 * u(rng), kout, 0.5 + 30 * u(rng));
        const CutPass sq = squarePass(s, kerf);
        const SteelCell cell(s, kerf);
        const EndCut cut(s);
        const SectionOutline& outline = cut.outline();
        const SteelLeadSamples samples =
            steelLeadSamples(s, sq, leads, s.knot_spacing_mm / s.speed_mm_s);
        SCOPED_TRACE(formatC("trial %d: %s mitres %.2f/%.2f kerf %.3f", trial,
                             s.section.designation.c_str(), s.cut.mitre_vertical_deg,
                             s.cut.mitre_horizontal_deg, kerf));
        for (const bool in : {true, false}) {
            const TorchTarget& at = in ? sq.samples.front() : sq.samples.back();
            const LeadSpec& lead = in ? leads.in : leads.out;
            std::vector<Vec3> pts = in ? steelLeadInPoints(at, lead.kind, lead.length_mm)
                                       : steelLeadOutPoints(at, lead.kind, lead.length_mm);
            for (const TorchTarget& t : in ? samples.before : samples.after)
                pts.push_back(t.p);
            // The start (end) face's plane: through the edge point, spanned by the bar's axis
            // and the outline segment's direction.
            const OutlineSegment& seg = outline.segments()[at.segment];
            const Vec3 faceNormal(0, seg.n0.x(), seg.n0.y());
            for (const Vec3& p : pts) {
                ++points;
                PlanarPose pose;
                EXPECT_TRUE(cell.pathPlanar(p, at.t, pose));
                const double across = acrossCut(s, p, at.edge_p);
                worstPlane = std::max(worstPlane, std::fabs(across - kerf / 2));
                minAcrossMinusHalfKerf = std::min(minAcrossMinusHalfKerf, across - kerf / 2);
                EXPECT_NEAR(across, kerf / 2, 1e-9);
                // Off the material: below the table face (over the slag bin) or outside the
                // outline in the section's (y, z).
                EXPECT_TRUE(p.z() <= 1e-9 || !outline.contains(Vec2(p.y(), p.z())))
                    << p.transpose();
                if (lead.kind == LeadKind::Line) {
                    const bool pierceMove =
                        (p - (in ? samples.pierce_point : at.p)).cross(at.t).norm() < 1e-9;
                    if (!pierceMove) {
                        worstFace = std::max(worstFace, std::fabs((p - at.p).dot(faceNormal)));
                        EXPECT_NEAR((p - at.p).dot(faceNormal), 0, 1e-9);
                    }
                }
            }
        }
    }
    std::printf("[figures] %zu lead points: |across - k/2| <= %.3g mm, min(across - k/2) = %.3g "
                "mm, line leads off the face plane <= %.3g mm\n",
                points, worstPlane, minAcrossMinusHalfKerf, worstFace);
}

// The arc joins the cut tangentially (its centre on the normal to the travel at the start) and
// has the arc length length_mm; the line runs straight along the cut's tangent, length_mm long.
TEST(SectionSteelLead, ArcTangentialWithItsArcLengthLineAlongTheCut) {
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> u(0, 1);
    double worstRadius = 0, worstLength = 0, worstTangent = 0;
    for (int trial = 0; trial < 12; ++trial) {
        const SectionSteelSpec s = randomSpec(rng);
        const CutPass sq = squarePass(s, 1.6);
        const double L = 0.5 + 40 * u(rng);
        for (const bool in : {true, false}) {
            const TorchTarget& at = in ? sq.samples.front() : sq.samples.back();
            const Vec3 e = at.edge.normalized(); // travel direction
            const Vec3 a = -at.t0.normalized();  // away from the material, in the arm's plane
            const double r = 2 * L / kPi;
            const Vec3 c = at.p + r * a; // the arc's centre
            std::vector<Vec3> arc = in ? steelLeadInPoints(at, LeadKind::Arc, L)
                                       : steelLeadOutPoints(at, LeadKind::Arc, L);
            // The quarter: from the first point to the join (lead-in), the join to the last.
            const Vec3 far = in ? arc.front() : arc.back();
            for (const Vec3& p : arc)
                worstRadius = std::max(worstRadius, std::fabs((p - c).norm() - r));
            const double angle = std::acos(
                std::clamp((far - c).normalized().dot((at.p - c).normalized()), -1.0, 1.0));
            worstLength = std::max(worstLength, std::fabs(r * angle - L));
            EXPECT_NEAR(r * angle, L, 1e-9);
            // Tangent at the join: the radius there is square to the travel.
            worstTangent = std::max(worstTangent, std::fabs((at.p - c).normalized().dot(e)));
            EXPECT_NEAR((at.p - c).dot(e), 0, 1e-9);
            // The next arc point goes on in the travel's sense (no cusp at the join).
            const Vec3 near = in ? arc.back() : arc.front();
            EXPECT_GT(in ? (at.p - near).dot(e) : (near - at.p).dot(e), 0);
            // Line: along the tangent, length_mm from the join, on the far side of the travel.
            const std::vector<Vec3> line = in ? steelLeadInPoints(at, LeadKind::Line, L)
                                              : steelLeadOutPoints(at, LeadKind::Line, L);
            ASSERT_EQ(line.size(), 1u);
            const Vec3 d = in ? Vec3(at.p - line[0]) : Vec3(line[0] - at.p);
            EXPECT_NEAR(d.norm(), L, 1e-9);
            EXPECT_NEAR(d.normalized().dot(e), 1, 1e-12);
        }
    }
    std::printf("[figures] arc radius error %.3g mm, arc length error %.3g mm, radius at the "
                "join . travel %.3g\n",
                worstRadius, worstLength, worstTangent);
}

// The torch fires with its nozzle the pierce height above the lead-in's first point along the
// torch axis (the tool point pierce - cut height back along the axis), then comes down along the
// axis to the cut height (the tool point on the point) before the lead-in.
TEST(SectionSteelLead, FiredAtPierceHeightAlongTheTorchAxisThenDownToCutHeight) {
    const SectionSteelSpec s = defaultSectionSteelSpec();
    const CutPass sq = squarePass(s, 1.6);
    const TorchTarget& start = sq.samples.front();
    const SteelLeadSpec leads = leadsOf(LeadKind::Arc, 8, LeadKind::None, 0);
    const SteelLeadSamples l = steelLeadSamples(s, sq, leads, s.knot_spacing_mm / s.speed_mm_s);
    const Vec3 axis = start.t.normalized();
    const Vec3 first = steelLeadInPoints(start, LeadKind::Arc, 8).front();
    EXPECT_NEAR((l.pierce_point - first).norm(), 0, 1e-12);
    EXPECT_NEAR((l.pierce_nozzle - l.pierce_point).dot(-axis), 3.8, 1e-12);
    EXPECT_NEAR((l.pierce_nozzle - l.pierce_point).cross(axis).norm(), 0, 1e-12);
    ASSERT_FALSE(l.before.empty());
    const TorchTarget& fired = l.before.front();
    EXPECT_EQ(fired.lead, kLeadPierce);
    const Vec3 up = fired.p - l.pierce_point;
    EXPECT_NEAR(up.dot(-axis), 3.8 - 1.5, 1e-12);
    EXPECT_NEAR(up.cross(axis).norm(), 0, 1e-12);
    // The nozzle (tool point + cut height back along the axis) is 3.8 mm above the point.
    EXPECT_NEAR(((fired.p - 1.5 * axis) - l.pierce_point).norm(), 3.8, 1e-12);
    // The pierce samples stay on the axis line and end on the point; then the lead-in.
    size_t k = 0;
    for (; k < l.before.size() && l.before[k].lead == kLeadPierce; ++k)
        EXPECT_NEAR((l.before[k].p - l.pierce_point).cross(axis).norm(), 0, 1e-9);
    ASSERT_LT(k, l.before.size());
    EXPECT_EQ(l.before[k].lead, kLeadIn);
    EXPECT_NEAR((l.before[k].p - l.pierce_point).norm(), 0, 1e-12);
    std::printf("[figures] pierce: nozzle %.3f mm above the point, tool point %.3f mm, %zu "
                "samples down to cut height, %zu lead-in samples, %.2f s before the cut\n",
                (l.pierce_nozzle - l.pierce_point).norm(), up.norm(), k, l.before.size() - k,
                l.before_s);
}

// A lead the cell cannot reach is refused naming the key, value, unit and the longest that
// fits; that length is then accepted.
TEST(SectionSteelLead, TooLongRefusedWithTheLongestThatFitsWhichIsAccepted) {
    SectionSteelSpec s = defaultSectionSteelSpec();
    const double kerf = 1.6;
    const SteelLeadSpec leads = leadsOf(LeadKind::Line, 60, LeadKind::None, 0);
    const SteelPlan free = planEndCut(s, kerf, leads);
    ASSERT_TRUE(free.ok) << free.problem;
    // A path-arm joint limit between the cut's range and the lead's: the lead cannot be cut.
    double cutMin[3] = {1e9, 1e9, 1e9}, leadMin[3] = {1e9, 1e9, 1e9};
    double cutMax[3] = {-1e9, -1e9, -1e9}, leadMax[3] = {-1e9, -1e9, -1e9};
    for (size_t k = 0; k < free.knots.size(); ++k) {
        if (free.info[k].pass != 0) continue;
        const bool lead = free.passes[0].samples[free.info[k].sample].lead != kLeadNone;
        for (int i = 0; i < 3; ++i) {
            const double d = rad2deg(free.knots[k][i]);
            (lead ? leadMin : cutMin)[i] = std::min((lead ? leadMin : cutMin)[i], d);
            (lead ? leadMax : cutMax)[i] = std::max((lead ? leadMax : cutMax)[i], d);
        }
    }
    int joint = -1;
    bool below = false;
    for (int i = 0; i < 3 && joint < 0; ++i) {
        if (leadMin[i] < cutMin[i] - 0.5)
            joint = i, below = true;
        else if (leadMax[i] > cutMax[i] + 0.5)
            joint = i;
    }
    ASSERT_GE(joint, 0) << "the lead stays inside the cut's joint range";
    const size_t j = static_cast<size_t>(joint);
    if (below)
        s.path_limits[j].min_deg = (cutMin[j] + leadMin[j]) / 2;
    else
        s.path_limits[j].max_deg = (cutMax[j] + leadMax[j]) / 2;
    const SteelPlan refused = planEndCut(s, kerf, leads);
    EXPECT_FALSE(refused.ok);
    EXPECT_EQ(refused.lead_key, "process.lead_in.length_mm");
    EXPECT_NE(refused.lead_problem.find("process.lead_in.length_mm = 60 mm"), std::string::npos)
        << refused.lead_problem;
    const size_t at = refused.lead_problem.find("the longest that fits is ");
    ASSERT_NE(at, std::string::npos) << refused.lead_problem;
    const double longest = std::stod(refused.lead_problem.substr(at + 25));
    EXPECT_GT(longest, 0);
    EXPECT_LT(longest, 60);
    SteelLeadSpec fits = leads;
    fits.in.length_mm = longest;
    const SteelPlan accepted = planEndCut(s, kerf, fits);
    EXPECT_TRUE(accepted.ok) << accepted.problem;
    EXPECT_TRUE(accepted.leads_added);
    std::printf("[figures] limit on path joint %d at %.2f deg: refused: %s\n[figures] %.3f mm "
                "accepted (%zu knots)\n",
                joint + 1, below ? s.path_limits[j].min_deg : s.path_limits[j].max_deg,
                refused.lead_problem.c_str(), longest, accepted.knots.size());
}

// No lead keys: the plan, the program's knots and path.csv are bit for bit as before.
TEST(SectionSteelLead, NoLeadKeysIdenticalProgram) {
    const Job job = plasmaSteelJob();
    const SectionSteelSpec& s = *job.machine_spec.as<SectionSteelSpec>();
    const SteelPlan before = planEndCut(s, 1.6);
    const SteelPlan after = planEndCut(s, 1.6, SteelLeadSpec{});
    ASSERT_EQ(before.knots.size(), after.knots.size());
    for (size_t k = 0; k < before.knots.size(); ++k)
        ASSERT_TRUE(before.knots[k] == after.knots[k]) << k;
    EXPECT_EQ(steelPathCsv(s, before), steelPathCsv(s, after));
    EXPECT_FALSE(after.leads_added);
    // Through the module: a job without lead keys plans what planEndCut plans.
    const MachineModule* m = findMachine(kSectionSteelId);
    const MachinePlan plan = m->plan(job, "", {});
    ASSERT_TRUE(plan.ok()) << plan.outcome.message;
    EXPECT_EQ(m->exportFile("path_csv", job, plan), steelPathCsv(s, before));
}

// The program's joints at the lead samples, through the path arm's forward kinematics, give the
// lead tool points; the module plans the job with its leads and says so.
TEST(SectionSteelLead, ForwardKinematicsReproducesTheLeadToolPoints) {
    Job job = plasmaSteelJob();
    job.process.lead_in = {LeadKind::Arc, 10, 0};
    job.process.lead_out = {LeadKind::Line, 6, 0};
    job.process.override.set(CutFigure::PierceHeightMm, 3.8);
    job.process.override.set(CutFigure::CutHeightMm, 1.5);
    const MachineModule* m = findMachine(kSectionSteelId);
    EXPECT_TRUE(m->validate(job).empty()) << m->validate(job).front().message;
    const MachinePlan mp = m->plan(job, "", {});
    ASSERT_TRUE(mp.ok()) << mp.outcome.message;
    EXPECT_NE(mp.summary.find("lead-in arc 10.0 mm"), std::string::npos) << mp.summary;
    const SteelPlan& plan = *static_cast<const SteelPlan*>(mp.data.get());
    ASSERT_TRUE(plan.leads_added);
    const SectionSteelSpec& s = *job.machine_spec.as<SectionSteelSpec>();
    const SteelCell cell(s, plan.kerf_mm);
    double worst = 0;
    size_t n[4] = {0, 0, 0, 0};
    for (size_t k = 0; k < plan.knots.size(); ++k) {
        if (plan.info[k].pass != 0) continue;
        const TorchTarget& t = plan.passes[0].samples[plan.info[k].sample];
        if (t.lead == kLeadNone) continue;
        ++n[t.lead];
        Vec3 p, d;
        cell.pathTorch({plan.knots[k][0], plan.knots[k][1], plan.knots[k][2]}, p, d);
        worst = std::max(worst, (p - t.p).norm());
        EXPECT_LT((p - t.p).norm(), 1e-6);
        EXPECT_LT((d - t.t).norm(), 1e-9);
        // The engine's tip model (the program's) gives the same point.
        EXPECT_LT((mp.program->tip_model->tip(plan.knots[k]) - t.p).norm(), 1e-6);
    }
    EXPECT_GT(n[kLeadPierce], 0u);
    EXPECT_GT(n[kLeadIn], 0u);
    EXPECT_GT(n[kLeadOut], 0u);
    // The CSV names the lead rows.
    const std::string csv = m->exportFile("path_csv", job, mp);
    EXPECT_NE(csv.find(",lead-in ("), std::string::npos);
    EXPECT_NE(csv.find(",pierce ("), std::string::npos);
    EXPECT_NE(csv.find(",lead-out ("), std::string::npos);
    std::printf("[figures] %zu pierce, %zu lead-in, %zu lead-out knots: FK error <= %.3g mm; "
                "cut time %.2f s\n",
                n[kLeadPierce], n[kLeadIn], n[kLeadOut], worst, plan.cut_time_s);
}

// The checks: heights missing (leadHeightProblem's key), an overlap on the open cut, leads in
// setup 2, the height overrides accepted with a lead (refused without).
TEST(SectionSteelLead, ValidationOfTheLeadKeys) {
    Job job = plasmaSteelJob();
    job.process.lead_in = {LeadKind::Line, 5, 0};
    EXPECT_TRUE(hasKey(issueKeys(job), "process.override.pierce_height_mm"));
    const MachinePlan refused = findMachine(kSectionSteelId)->plan(job, "", {});
    EXPECT_FALSE(refused.ok());
    EXPECT_EQ(refused.outcome.key, "process.override.pierce_height_mm");
    job.process.override.set(CutFigure::PierceHeightMm, 3.8);
    EXPECT_TRUE(hasKey(issueKeys(job), "process.override.cut_height_mm"));
    job.process.override.set(CutFigure::CutHeightMm, 1.5);
    EXPECT_TRUE(issueKeys(job).empty());
    job.process.lead_out.overlap_mm = 2;
    EXPECT_TRUE(hasKey(issueKeys(job), "process.lead_out.overlap_mm"));
    job.process.lead_out.overlap_mm = 0;
    Job two = job;
    auto& s2 = *two.machine_spec.as<SectionSteelSpec>();
    s2.cut.setup = 2;
    s2.cut.flanges.type = GrooveType::K;
    EXPECT_TRUE(hasKey(issueKeys(two), "process.lead_in.kind"));
    Job none = job;
    none.process.lead_in = {};
    EXPECT_TRUE(hasKey(issueKeys(none), "process.override.pierce_height_mm"));
}
