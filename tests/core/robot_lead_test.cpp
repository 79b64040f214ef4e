// Lead-in / lead-out and the pierce on the pipe robot (issue 24, robot_lead.h). Checked from
// outside the lead code: the lead points lie on the work pipe (a cylinder) and inside the other
// pipe (the scrap: the branch bore for the hole, the main pipe for the branch end), at least k/2
// from the edge measured on the test's own developed edge; the arc joins the cut tangentially
// with the arc length asked; the line leaves square; the pierce stands pierce - cut height over
// the surface on the torch axis and comes down along it; a lead too long is refused with the
// longest that fits, which is then accepted; the joint program's FK gives the lead points back.
#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/machine/pipe_joint_section.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"
#include "core/machines/pipe_robot/pipe_robot_program.h"
#include "core/machines/pipe_robot/robot_lead.h"
#include "core/process/kerf_offset.h"
#include "core/process/process_spec.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace cutcell;

namespace {

constexpr double kPierceMm = 3.8, kCutMm = 1.5;

void setProcess(Job& job, double kerf_mm) {
    job.process.used = true;
    job.process.process = CutProcess::Plasma;
    job.process.material = "mild_steel";
    job.process.consumable = "Powermax65/85 45A shielded";
    job.process.thickness_mm = 3.0;
    if (kerf_mm > 0) job.process.override.set(CutFigure::KerfMm, kerf_mm);
    job.process.override.set(CutFigure::PierceHeightMm, kPierceMm);
    job.process.override.set(CutFigure::CutHeightMm, kCutMm);
}

// As the kerf tests: random pipe pairs, angles, offsets and bevels.
Job randomJob(std::mt19937& rng, CutTarget target) {
    std::uniform_real_distribution<double> u(0, 1);
    Job job;
    job.main_pipe.radius_mm = 20 + 180 * u(rng);
    job.branch_pipe.radius_mm = 5 + (job.main_pipe.radius_mm - 6) * u(rng);
    job.branch_pipe.wall_mm = 0.5 + 0.3 * job.branch_pipe.radius_mm * u(rng);
    job.main_pipe.wall_mm = 0.5 + 0.2 * job.branch_pipe.radius_mm * u(rng);
    const double room = 0.95 * (job.main_pipe.radius_mm - job.branch_pipe.radius_mm);
    job.eccentricity_mm = room * (2 * u(rng) - 1);
    job.angle_deg = 15 + 75 * u(rng);
    job.cut.target = target;
    job.cut.bevel_deg = 60 * u(rng) - 30;
    return job;
}

double randomKerf(std::mt19937& rng, const Job& job) {
    const double bore = job.branch_pipe.radius_mm - job.branch_pipe.wall_mm;
    const double cap = std::min({4.0, 0.15 * job.branch_pipe.radius_mm, 0.5 * bore});
    return std::uniform_real_distribution<double>(0.05, cap)(rng);
}

// The scrap, independent of the lead code: inside the branch bore (the hole's disc) or inside
// the main pipe (the branch end's off-cut). Main frame.
double branchRadial(const Job& job, const Vec3& p) {
    const double a = deg2rad(job.angle_deg);
    const Vec3 axis(0, std::sin(a), std::cos(a));
    const Vec3 d = p - Vec3(job.eccentricity_mm, 0, 0);
    return (d - d.dot(axis) * axis).norm();
}
bool inScrap(const Job& job, const Vec3& p_main) {
    if (job.cut.target == CutTarget::Main)
        return branchRadial(job, p_main) < job.branch_pipe.radius_mm - job.branch_pipe.wall_mm;
    return std::hypot(p_main.x(), p_main.y()) < job.main_pipe.radius_mm;
}

// The test's own developed edge (z, R phi of the work frame, 0.05 mm apart, unwrapped) and the
// distance of a point of the work pipe to it, every copy round the pipe tried.
struct DevEdge {
    double R;
    std::vector<std::array<double, 2>> pts;
    DevEdge(const CutGeometry& geo) : R(geo.workRadius()) {
        double last = 0;
        for (const CutPoint& c : geo.sampleEqualArcLength(0.05)) {
            double phi = std::atan2(c.p_work.y(), c.p_work.x());
            if (!pts.empty()) phi = last + std::remainder(phi - last, 2 * kPi);
            last = phi;
            pts.push_back({c.p_work.z(), R * phi});
        }
    }
    double distance(const Vec3& p) const {
        const double phi = std::atan2(p.y(), p.x());
        double best = 1e300;
        for (int turn = -2; turn <= 2; ++turn) {
            const double z = p.z(), u = R * (phi + 2 * kPi * turn);
            for (size_t i = 0; i + 1 < pts.size(); ++i) {
                const double ax = pts[i][0], au = pts[i][1];
                const double dx = pts[i + 1][0] - ax, du = pts[i + 1][1] - au;
                const double l2 = dx * dx + du * du;
                const double t =
                    l2 > 0 ? std::clamp(((z - ax) * dx + (u - au) * du) / l2, 0.0, 1.0) : 0.0;
                best = std::min(best, std::hypot(z - ax - t * dx, u - au - t * du));
            }
        }
        return best;
    }
};

// The longest length the message offers ("the longest that fits is X mm").
double offered(const std::string& message) {
    const std::string tag = "the longest that fits is ";
    const size_t at = message.find(tag);
    if (at == std::string::npos) return -1;
    return std::stod(message.substr(at + tag.size()));
}

double angleDeg(const Vec3& a, const Vec3& b) {
    return rad2deg(std::atan2(a.cross(b).norm(), a.dot(b)));
}

// The default robot job (reachable) cut by plasma with leads.
Job leadJob(LeadKind in, double inLen, LeadKind out, double outLen, double overlap,
            double kerf = 1.5) {
    Job job = defaultJob();
    setProcess(job, kerf);
    syncProcessSpeed(job);
    job.process.lead_in = {in, inLen, 0};
    job.process.lead_out = {out, outLen, overlap};
    return job;
}

} // namespace

// Every lead point on the nominal work pipe (1e-9 mm), in the scrap and at least k/2 from the
// edge, over random pipe pairs, leads and kerfs; a lead that does not fit is refused with the
// longest that does, which is then made.
TEST(RobotLead, LeadPointsOnTheSurfaceOnTheScrapSide) {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> U(0, 1);
    double worstSurface = 0, worstClearance = 1e300;
    int refused = 0, cases = 0;
    for (int c = 0; c < 40; ++c) {
        Job job = randomJob(rng, c % 2 ? CutTarget::Main : CutTarget::Branch);
        const double k = randomKerf(rng, job);
        setProcess(job, k);
        const double bore = job.branch_pipe.radius_mm - job.branch_pipe.wall_mm;
        job.process.lead_in = {U(rng) < 0.5 ? LeadKind::Line : LeadKind::Arc,
                               (0.05 + 2.5 * U(rng)) * bore, 0};
        job.process.lead_out = {U(rng) < 0.5 ? LeadKind::Line : LeadKind::Arc,
                                (0.05 + 2.5 * U(rng)) * bore, 3 * U(rng)};
        const CutGeometry geo(job);
        const KerfPathSpec kerf = kerfPathSpecFor(job, geo);
        RobotLeadPath leads(job, geo, kerf, k);
        if (!leads.ok()) {
            ++refused;
            const double fits = offered(leads.problem());
            ASSERT_GT(fits, 0) << leads.problem();
            EXPECT_NE(leads.problem().find(leads.problemKey()), std::string::npos);
            (leads.problemKey() == "process.lead_in.length_mm" ? job.process.lead_in
                                                               : job.process.lead_out)
                .length_mm = fits;
            leads = RobotLeadPath(job, geo, kerf, k);
            if (!leads.ok()) { // the other lead may not fit either: take its offer too
                const double fits2 = offered(leads.problem());
                ASSERT_GT(fits2, 0) << leads.problem();
                job.process.lead_out.length_mm = fits2;
                leads = RobotLeadPath(job, geo, kerf, k);
            }
            ASSERT_TRUE(leads.ok()) << leads.problem();
        }
        ++cases;
        const DevEdge edge(geo);
        const double R = geo.workRadius();
        const double from[2] = {0, leads.leadInMm() + leads.cutMm() + leads.overlapMm()};
        const double len[2] = {leads.leadInMm(), leads.leadOutMm()};
        for (int part = 0; part < 2; ++part)
            for (int i = 0; i <= 100; ++i) {
                // The lead-in without its joint with the cut, the lead-out without its start.
                if ((part == 0 && i == 100) || (part == 1 && i == 0) || len[part] == 0) continue;
                PathPart what;
                const CutPoint p = leads.travelAt(from[part] + len[part] * i / 100, &what);
                ASSERT_EQ(what, part == 0 ? PathPart::LeadIn : PathPart::LeadOut);
                const double off = std::fabs(std::hypot(p.p_work.x(), p.p_work.y()) - R);
                worstSurface = std::max(worstSurface, off);
                EXPECT_LT(off, 1e-9);
                // The torch keeps the joint's angle to the surface normal (carried round).
                const CutPoint& joint =
                    part == 0 ? leads.torchAt(0) : leads.torchAt(leads.overlapMm());
                const Vec3 nJ = Vec3(joint.p_work.x(), joint.p_work.y(), 0).normalized();
                const Vec3 nP = Vec3(p.p_work.x(), p.p_work.y(), 0).normalized();
                EXPECT_NEAR(p.approach_work.dot(nP), joint.approach_work.dot(nJ), 1e-9);
                EXPECT_NEAR(p.approach_work.z(), joint.approach_work.z(), 1e-12);
                const double d = edge.distance(p.p_work);
                worstClearance = std::min(worstClearance, d - k / 2);
                EXPECT_GE(d, k / 2 - 0.01) << "case " << c << " part " << part << " i " << i;
                // In the scrap (a point within 0.01 mm of the edge may round either way).
                if (d > 0.01) {
                    EXPECT_TRUE(inScrap(job, p.p_main)) << "case " << c << " i " << i;
                }
            }
    }
    std::printf("%d cases (%d refused first, then made at the offered length): largest distance "
                "off the pipe %.3g mm, smallest clearance beyond k/2 %.4f mm\n",
                cases, refused, worstSurface, worstClearance);
    EXPECT_GT(refused, 0); // the refusal path was taken
}

// The arc joins the cut tangentially with arc length length_mm; the line leaves it square.
TEST(RobotLead, ArcTangentAndLengthLineSquare) {
    std::mt19937 rng(5);
    double worstJoin = 0, worstLen = 0, worstSquare = 0;
    for (int c = 0; c < 20; ++c) {
        Job job = randomJob(rng, c % 2 ? CutTarget::Main : CutTarget::Branch);
        const double k = randomKerf(rng, job);
        setProcess(job, k);
        const double L = 0.05 * (job.branch_pipe.radius_mm - job.branch_pipe.wall_mm);
        const CutGeometry geo(job);
        const KerfPathSpec kerf = kerfPathSpecFor(job, geo);
        for (LeadKind kind : {LeadKind::Arc, LeadKind::Line}) {
            job.process.lead_in = {kind, L, 0};
            job.process.lead_out = {kind, L, 0};
            const RobotLeadPath leads(job, geo, kerf, k);
            ASSERT_TRUE(leads.ok()) << leads.problem();
            const double h = 1e-3 * L, in = leads.leadInMm(), end = in + leads.cutMm();
            // The cut's direction at its start and end, from the torch path itself.
            const Vec3 cutIn = leads.travelAt(in + h).p_work - leads.travelAt(in).p_work;
            const Vec3 cutOut = leads.travelAt(end).p_work - leads.travelAt(end - h).p_work;
            const Vec3 leadIn = leads.travelAt(in).p_work - leads.travelAt(in - h).p_work;
            const Vec3 leadOut =
                leads.travelAt(end + h).p_work - leads.travelAt(end).p_work; // overlap 0
            if (kind == LeadKind::Arc) {
                worstJoin =
                    std::max({worstJoin, angleDeg(cutIn, leadIn), angleDeg(cutOut, leadOut)});
                EXPECT_LT(angleDeg(cutIn, leadIn), 0.5);
                EXPECT_LT(angleDeg(cutOut, leadOut), 0.5);
                // Arc length along the surface, by chords.
                for (int part = 0; part < 2; ++part) {
                    double s = 0;
                    const double a = part == 0 ? 0 : end;
                    Vec3 prev = leads.travelAt(a).p_work;
                    for (int i = 1; i <= 2000; ++i) {
                        const Vec3 q = leads.travelAt(a + L * i / 2000).p_work;
                        s += (q - prev).norm();
                        prev = q;
                    }
                    worstLen = std::max(worstLen, std::fabs(s - L));
                    EXPECT_NEAR(s, L, 1e-4 * L);
                }
            } else {
                const double sq = std::max(std::fabs(angleDeg(cutIn, leadIn) - 90),
                                           std::fabs(angleDeg(cutOut, leadOut) - 90));
                worstSquare = std::max(worstSquare, sq);
                EXPECT_LT(sq, 0.5);
            }
        }
    }
    std::printf("arc: largest angle at the joint %.4f deg, largest length error %.2e mm; line: "
                "largest deviation from square %.4f deg\n",
                worstJoin, worstLen, worstSquare);
}

// The plan: the first knot is the pierce, the torch tip pierce_height over the surface on the
// torch axis; the descent runs down that axis to the pierce point; the torch is lit there
// (the program's pierce dwell is the chart's delay); FK of every knot's joints gives its tool
// point and axis back.
TEST(RobotLead, PierceDescentAndFkRoundTrip) {
    for (LeadKind kind : {LeadKind::Arc, LeadKind::Line}) {
        Job job = leadJob(kind, 6, kind, 4, 2);
        const CutPlan plan = planCut(job);
        ASSERT_TRUE(plan.reachable) << plan.problem;
        ASSERT_TRUE(plan.leads);
        const PipeRobot robot(pipeRobotSpec(job).dh);
        size_t firstSurface = 0;
        while (plan.knots[firstSurface].part == PathPart::Descent)
            ++firstSurface;
        ASSERT_GE(firstSurface, 2u);
        const Vec3 P = plan.knots[firstSurface].cut.p_work;
        const Vec3 a = plan.knots[0].cut.approach_work;
        EXPECT_EQ(plan.knots[firstSurface].part, PathPart::LeadIn);
        // The torch tip stands the cut height over its tool point (the planner's convention).
        const Vec3 tip0 = plan.knots[0].cut.p_work - kCutMm * a;
        EXPECT_NEAR((P - tip0).dot(a), kPierceMm, 1e-9);
        EXPECT_LT(((P - tip0) - (P - tip0).dot(a) * a).norm(), 1e-9);
        // Down the axis, never back up, never below the surface.
        double offAxis = 0, last = 1e300;
        for (size_t i = 0; i < firstSurface; ++i) {
            const Vec3 w = P - plan.knots[i].cut.p_work;
            offAxis = std::max(offAxis, (w - w.dot(a) * a).norm());
            EXPECT_LE(w.dot(a), last + 1e-12);
            EXPECT_GE(w.dot(a), -1e-12);
            EXPECT_LT(angleDeg(plan.knots[i].cut.approach_work, a), 1e-9);
            last = w.dot(a);
        }
        EXPECT_LT(offAxis, 1e-9);
        EXPECT_EQ(plan.knots.back().part, PathPart::LeadOut);
        // FK round trip over every knot (descent, leads, cut).
        double worstTip = 0, worstAxis = 0;
        for (const PlannedPoint& p : plan.knots) {
            const Pose tool = robot.forward(p.q.segment<kArmJointCount>(1));
            const Vec3 want = robot.baseFromWork(p.q[0]) * p.cut.p_work;
            worstTip = std::max(worstTip, (tool.translation() - want).norm());
            worstAxis = std::max(worstAxis, angleDeg(tool.linear().col(2), p.approach_base));
        }
        EXPECT_LT(worstTip, 1e-6);
        EXPECT_LT(worstAxis, 1e-6);
        const auto program = buildPipeRobotProgram(job, plan);
        const ProcessSettings s = resolveProcess(job.process, cutPartWallMm(job));
        EXPECT_EQ(program->pierce_s, s.effective.get(CutFigure::PierceDelayS).value_or(0.0));
        EXPECT_LT(program->cruise_from_s, program->cruise_to_s);
        std::printf("%s: %zu knots (%zu descent), cut %.2f s of %.2f s, pierce %.2f s; FK: tip "
                    "%.2e mm, axis %.2e deg\n",
                    toString(kind), plan.knots.size(), firstSurface,
                    program->cruise_to_s - program->cruise_from_s, plan.cut_time_s,
                    program->pierce_s, worstTip, worstAxis);
    }
}

// Too long: refused naming key, value, unit and the longest that fits; that length is made.
TEST(RobotLead, TooLongIsRefusedWithTheLongestThatFits) {
    for (const char* key : {"process.lead_in.length_mm", "process.lead_out.length_mm"}) {
        for (LeadKind kind : {LeadKind::Line, LeadKind::Arc}) {
            const bool in = std::string(key) == "process.lead_in.length_mm";
            Job job = in ? leadJob(kind, 200, LeadKind::None, 0, 0)
                         : leadJob(LeadKind::None, 0, kind, 200, 0);
            const PipeRobotModule module;
            const MachinePlan refused = module.plan(job, {}, {});
            ASSERT_FALSE(refused.ok());
            EXPECT_EQ(refused.outcome.key, key);
            const std::string& m = refused.outcome.message;
            EXPECT_NE(m.find(std::string(key) + " = 200 mm is too long for the hole"),
                      std::string::npos)
                << m;
            const double fits = offered(m);
            ASSERT_GT(fits, 0) << m;
            (in ? job.process.lead_in : job.process.lead_out).length_mm = fits;
            const MachinePlan made = module.plan(job, {}, {});
            EXPECT_TRUE(made.ok()) << made.outcome.message;
            std::printf("%s %s: the longest that fits %.3f mm\n", key, toString(kind), fits);
        }
    }
}

// No lead keys (or leads "none" in the file): the program is the one without leads, bit for bit.
TEST(RobotLead, NoLeadKeysSameProgram) {
    Job job = leadJob(LeadKind::None, 0, LeadKind::None, 0, 0);
    const std::string text = json::write(jobToJson(job));
    std::string withNone = text;
    const size_t at = withNone.find("\"material\"");
    ASSERT_NE(at, std::string::npos);
    withNone.insert(at, R"("lead_in": {"kind": "none"}, "lead_out": {"kind": "none"}, )");
    const CutPlan a = planCut(parseJob(text)), b = planCut(parseJob(withNone));
    ASSERT_FALSE(a.leads);
    ASSERT_FALSE(b.leads);
    ASSERT_EQ(a.knots.size(), b.knots.size());
    EXPECT_EQ(a.cut_time_s, b.cut_time_s);
    for (size_t i = 0; i < a.knots.size(); ++i)
        ASSERT_EQ(a.knots[i].q, b.knots[i].q) << i;
    // ... and the same cut as with leads, the lead-free plan's knots on the leads' cut part.
    const CutPlan l = planCut(leadJob(LeadKind::Arc, 5, LeadKind::Arc, 5, 0));
    ASSERT_TRUE(l.leads);
    const CutGeometry geo(job);
    const RobotLeadPath leads(leadJob(LeadKind::Arc, 5, LeadKind::Arc, 5, 0), geo,
                              kerfPathSpecFor(job, geo), a.kerf_mm);
    double worst = 0;
    for (const PlannedPoint& p : a.knots)
        worst = std::max(worst, (leads.torchAt(p.cut.s_mm).p_work - p.cut.p_work).norm());
    EXPECT_LT(worst, 1e-12);
}
