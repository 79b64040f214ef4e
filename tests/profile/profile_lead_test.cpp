// Lead-in / lead-out on the profile cutter's closed cut and the torch height as a simulated Z
// axis (issue 24): the leads lie on the scrap side for random joints, LinuxCNC's interpreter
// (rs274, skipped where not installed) reads the pierce, the dwell and the lead-in before the
// cut, a job without lead keys gives the same program as before, refusals name key, value,
// unit and limit, and the keys round trip.
#include "core/job/job_io.h"
#include "core/machines/profile_cutter/gcode_export.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"
#include "core/machines/profile_cutter/profile_lead.h"
#include "core/process/process_spec.h"
#include "profile_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace cutcell {
namespace {

void setProcess(Job& job, double kerf_mm) {
    test::setPlasmaProcess(job);
    if (kerf_mm > 0) job.process.override.set(CutFigure::KerfMm, kerf_mm);
}

void setLeads(Job& job, LeadKind in, double inLen, LeadKind out, double outLen,
              double overlap = 0) {
    job.process.override.set(CutFigure::PierceHeightMm, 3.8);
    job.process.override.set(CutFigure::CutHeightMm, 1.5);
    job.process.lead_in = {in, inLen, 0};
    job.process.lead_out = {out, outLen, overlap};
}

// The test's own scrap-side test on the part's edge (developed, u = R A): the branch end's
// off-cut lies beyond the edge's X at the point's A; the hole's inside is inside the polygon.
bool scrapSide(const ProfileCut& edge, double x, double a_deg) {
    const double R = edge.work_radius_mm;
    const size_t n = edge.points.size();
    if (edge.target == CutTarget::Branch) {
        double a = std::fmod(a_deg - edge.points[0].a_deg, 360.0);
        if (a < 0) a += 360.0;
        a += edge.points[0].a_deg;
        for (size_t i = 0; i < n; ++i) {
            const ProfilePoint p = edge.closedAt(i), q = edge.closedAt(i + 1);
            if (a >= p.a_deg && a <= q.a_deg) {
                const double t = q.a_deg > p.a_deg ? (a - p.a_deg) / (q.a_deg - p.a_deg) : 0;
                return x > p.x_mm + t * (q.x_mm - p.x_mm);
            }
        }
        ADD_FAILURE() << "A = " << a_deg << " not on the edge";
        return false;
    }
    bool inside = false;
    const double u = R * deg2rad(a_deg);
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const double xi = edge.points[i].x_mm, ui = R * deg2rad(edge.points[i].a_deg);
        const double xj = edge.points[j].x_mm, uj = R * deg2rad(edge.points[j].a_deg);
        if ((ui > u) != (uj > u) && x < xi + (u - ui) * (xj - xi) / (uj - ui)) inside = !inside;
    }
    return inside;
}

// Distance on the developed surface to the edge's closed polyline.
double edgeDistance(const ProfileCut& c, double x, double a_deg) {
    const double R = c.work_radius_mm;
    double best = 1e300;
    for (size_t i = 0; i < c.points.size(); ++i) {
        const ProfilePoint p = c.closedAt(i), q = c.closedAt(i + 1);
        double aa = a_deg;
        if (c.a_per_turn_deg > 0) aa += 360.0 * std::round((p.a_deg - a_deg) / 360.0);
        const double ux = q.x_mm - p.x_mm, uy = R * deg2rad(q.a_deg - p.a_deg);
        const double vx = x - p.x_mm, vy = R * deg2rad(aa - p.a_deg);
        const double len2 = ux * ux + uy * uy;
        const double t = len2 > 0 ? std::clamp((vx * ux + vy * uy) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(vx - t * ux, vy - t * uy));
    }
    return best;
}

// Lead-in (and lead-out) points lie on the scrap side, at least k/2 off the part's edge (to
// the chords' 0.01 mm), for random joints, both targets, line and arc.
TEST(ProfileLead, LeadsLieOnTheScrapSideForRandomJoints) {
    std::mt19937 rng(4242);
    std::uniform_real_distribution<double> U(0, 1);
    double leastClearance = 1e300, worstJoinDeg = 0;
    size_t points = 0;
    for (int k = 0; k < 24; ++k) {
        Job job = test::randomProfileJob(rng, k % 2 ? CutTarget::Main : CutTarget::Branch);
        const double kerf = k % 3 == 0 ? 0.0 : 0.5 + 1.5 * U(rng);
        setProcess(job, kerf);
        const LeadKind kind = (k / 2) % 2 ? LeadKind::Arc : LeadKind::Line;
        const double L = std::min(8.0, (0.1 + 0.25 * U(rng)) * job.branch_pipe.radius_mm);
        setLeads(job, kind, L, kind == LeadKind::Arc ? LeadKind::Line : LeadKind::Arc, 0.5 * L,
                 k % 4 == 0 ? 1.0 : 0.0);
        const ProfileCut cut = computeProfileCut(job, 720);
        ASSERT_TRUE(cut.kerf_problem.empty()) << cut.kerf_problem;
        const ProfileCut edge = computeProfileEdge(job, 720);
        const ProfileLeads leads = computeProfileLeads(job, cut, edge);
        ASSERT_TRUE(leads.problem.empty()) << leads.problem;
        ASSERT_TRUE(leads.used);
        ASSERT_FALSE(leads.lead_in.empty());
        ASSERT_FALSE(leads.lead_out.empty());
        for (const auto* pts : {&leads.lead_in, &leads.lead_out})
            for (const ProfilePoint& p : *pts) {
                const double d = edgeDistance(edge, p.x_mm, p.a_deg);
                const bool scrap = scrapSide(edge, p.x_mm, p.a_deg);
                EXPECT_TRUE(scrap || d < 0.01)
                    << "job " << k << ": lead point X " << p.x_mm << " A " << p.a_deg
                    << " inside the part, " << d << " mm from the edge";
                EXPECT_GE(d, kerf / 2 - 0.01) << "job " << k;
                leastClearance = std::min(leastClearance, d - kerf / 2);
                ++points;
            }
        // The pierce point: L from the start (line), r sqrt(2) with r = 2 L / pi (arc).
        const double R = cut.work_radius_mm;
        const ProfilePoint s = leads.lead_in.front(), p0 = cut.points.front();
        const double reach = std::hypot(s.x_mm - p0.x_mm, R * deg2rad(s.a_deg - p0.a_deg));
        EXPECT_NEAR(reach, kind == LeadKind::Line ? L : 2 * L / kPi * std::sqrt(2.0), 1e-9);
        if (kind == LeadKind::Arc) {
            // Tangential join: the last lead-in chord is within one arc step of the cut's
            // direction at the start.
            const ProfilePoint q = leads.lead_in.back(), p1 = cut.points[1];
            const ProfilePoint pn = cut.closedAt(cut.points.size() - 1);
            const double ax = p0.x_mm - q.x_mm, au = R * deg2rad(p0.a_deg - q.a_deg);
            const double bx = p1.x_mm - pn.x_mm,
                         bu = R * deg2rad(p1.a_deg - (pn.a_deg - cut.a_per_turn_deg));
            const double ang = rad2deg(std::acos(std::clamp(
                (ax * bx + au * bu) / std::hypot(ax, au) / std::hypot(bx, bu), -1.0, 1.0)));
            worstJoinDeg = std::max(worstJoinDeg, ang);
        }
    }
    std::printf("leads on the scrap side: %zu points, least clearance beyond k/2 %.4f mm; arc "
                "join: worst chord-to-tangent angle %.3f deg\n",
                points, leastClearance, worstJoinDeg);
    EXPECT_LT(worstJoinDeg, 90.0 / 16 / 2 + 0.5);
}

Job leadJob(CutTarget target) {
    Job job = test::exampleProfileJob();
    job.cut.target = target;
    setProcess(job, 1.2);
    job.process.override.set(CutFigure::PierceDelayS, 0.7);
    setLeads(job, LeadKind::Arc, 5, LeadKind::Line, 3, 1.5);
    return job;
}

std::string planGcode(const Job& job, MachinePlan* planOut = nullptr) {
    const ProfileCutterModule m;
    const MachinePlan plan = m.plan(job, "", PlanOptions{});
    EXPECT_TRUE(plan.outcome.ok()) << plan.outcome.message;
    if (planOut) *planOut = plan;
    return plan.outcome.ok() ? m.exportFile("gcode", job, plan) : std::string();
}

struct Canon {
    std::string name;
    double x = 0, z = 0, a = 0, value = 0;
};

std::vector<Canon> readCanon(const std::string& canon) {
    std::vector<Canon> out;
    std::istringstream in(canon);
    std::string line;
    while (std::getline(in, line)) {
        for (const char* name : {"STRAIGHT_TRAVERSE", "STRAIGHT_FEED"}) {
            const size_t at = line.find(std::string(name) + "(");
            Canon c{name};
            double y = 0;
            if (at != std::string::npos &&
                std::sscanf(line.c_str() + at + std::strlen(name) + 1, "%lf, %lf, %lf, %lf", &c.x,
                            &y, &c.z, &c.a) == 4)
                out.push_back(c);
        }
        for (const char* name : {"DWELL", "START_SPINDLE_CLOCKWISE", "STOP_SPINDLE_TURNING"}) {
            const size_t at = line.find(std::string(name) + "(");
            if (at == std::string::npos) continue;
            Canon c{name};
            std::sscanf(line.c_str() + at + std::strlen(name) + 1, "%lf", &c.value);
            out.push_back(c);
        }
    }
    return out;
}

// rs274 reads: Z to the pierce height, rapid to the pierce point, torch on, a dwell of the
// pierce delay, Z down to the cut height, the lead-in moves, then the cut, then the lead-out.
TEST(ProfileLead, Rs274ReadsPierceDwellLeadInThenCut) {
    int status = 0;
    const std::string rs274 = test::findRs274();
    if (rs274.empty()) GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
    const auto dir =
        std::filesystem::temp_directory_path() / ("cutcell_lead_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    double worst = 0;
    for (CutTarget target : {CutTarget::Branch, CutTarget::Main}) {
        const Job job = leadJob(target);
        MachinePlan plan;
        const std::string g = planGcode(job, &plan);
        const auto* data = static_cast<const ProfileCutterPlanData*>(plan.data.get());
        ASSERT_TRUE(data && data->leads.used);
        const ProfileLeads& L = data->leads;
        const ProfileCut& cut = data->cut;
        EXPECT_NE(g.find("(lead-in)"), std::string::npos);
        EXPECT_NE(g.find("(cut)"), std::string::npos);
        EXPECT_NE(g.find("(lead-out)"), std::string::npos);
        EXPECT_NE(g.find("G4 P0.700 (pierce)"), std::string::npos);
        const auto file = dir / (std::string("lead_") + toString(target) + ".ngc");
        writeFileAtomically(file.string(), g);
        const std::string out = test::runRs274(rs274, file.string(), &status);
        ASSERT_EQ(status, 0) << out;
        const std::vector<Canon> c = readCanon(out);
        size_t i = 0;
        auto next = [&](const char* name) -> const Canon& {
            while (i < c.size() && c[i].name != name)
                ++i;
            EXPECT_LT(i, c.size()) << "no " << name;
            static const Canon none{};
            return i < c.size() ? c[i++] : none;
        };
        // The torch up to the pierce height first (where it stands), then the rapid at it.
        const Canon& up = next("STRAIGHT_TRAVERSE");
        EXPECT_NEAR(up.z, 3.8, 1e-9);
        const Canon& rapid = next("STRAIGHT_TRAVERSE");
        EXPECT_NEAR(rapid.x, L.lead_in.front().x_mm, 1e-4);
        EXPECT_NEAR(rapid.a, L.lead_in.front().a_deg, 1e-4);
        EXPECT_NEAR(rapid.z, 3.8, 1e-9);
        EXPECT_EQ(c[i].name, "START_SPINDLE_CLOCKWISE");
        EXPECT_NEAR(next("DWELL").value, 0.7, 1e-9);
        const Canon& down = next("STRAIGHT_FEED");
        EXPECT_NEAR(down.z, 1.5, 1e-9);
        EXPECT_NEAR(down.x, rapid.x, 1e-9);
        std::vector<ProfilePoint> expected(L.lead_in.begin() + 1, L.lead_in.end());
        for (size_t k = 0; k <= cut.points.size(); ++k)
            expected.push_back(cut.closedAt(k));
        expected.insert(expected.end(), L.lead_out.begin(), L.lead_out.end());
        size_t feeds = 0;
        for (; i < c.size() && c[i].name == "STRAIGHT_FEED"; ++i, ++feeds) {
            ASSERT_LT(feeds, expected.size());
            EXPECT_NEAR(c[i].z, 1.5, 1e-9);
            worst = std::max({worst, std::fabs(c[i].x - expected[feeds].x_mm),
                              std::fabs(c[i].a - expected[feeds].a_deg)});
        }
        EXPECT_EQ(feeds, expected.size());
        EXPECT_EQ(c[i].name, "STOP_SPINDLE_TURNING");
        std::printf("%s: rs274 read %zu lead-in + %zu cut + %zu lead-out feeds, worst |d| "
                    "%.6f\n",
                    toString(target), L.lead_in.size(), cut.points.size(), L.lead_out.size(),
                    worst);
    }
    std::filesystem::remove_all(dir);
    EXPECT_LT(worst, 1e-4 + 1e-9);
}

// No lead keys (or "none"): the plan's cut and the G-code are what they were without the keys.
TEST(ProfileLead, NoLeadKeysLeaveTheProgramUnchanged) {
    for (CutTarget target : {CutTarget::Branch, CutTarget::Main})
        for (double kerf : {0.0, 1.2}) {
            Job job = test::exampleProfileJob();
            job.cut.target = target;
            if (kerf > 0) setProcess(job, kerf);
            const ProfileCut cut = computeProfileCut(job);
            const std::string before = profileGcode(job, cut);
            MachinePlan plan;
            const std::string exported = planGcode(job, &plan);
            EXPECT_EQ(exported, before);
            EXPECT_EQ(before.find(" Z"), std::string::npos);
            EXPECT_EQ(plan.summary.find("lead"), std::string::npos);
            if (kerf > 0) {
                // Read back from the file (the chart then sets the speed): "none" or absent.
                const std::string without = planGcode(parseJob(json::write(jobToJson(job))));
                job.process.lead_in = {LeadKind::None, 0, 0};
                job.process.lead_out = {LeadKind::None, 0, 0};
                const std::string text = json::write(jobToJson(job));
                EXPECT_EQ(text.find("lead_"), std::string::npos);
                EXPECT_FALSE(without.empty());
                EXPECT_EQ(planGcode(parseJob(text)), without);
                std::string explicitNone = text;
                const size_t at = explicitNone.find("\"override\"");
                ASSERT_NE(at, std::string::npos);
                explicitNone.insert(at, "\"lead_in\": {\"kind\": \"none\"}, ");
                EXPECT_EQ(planGcode(parseJob(explicitNone)), without);
            }
        }
}

std::vector<JobIssue> issuesAt(const Job& job, const std::string& key) {
    std::vector<JobIssue> out;
    for (const JobIssue& i : ProfileCutterModule().validate(job))
        if (i.key == key) out.push_back(i);
    return out;
}

TEST(ProfileLead, RefusalsNameKeyValueUnitAndLimit) {
    // Too long for the hole: it would reach the other side.
    Job job = leadJob(CutTarget::Main);
    job.process.lead_in.length_mm = 100;
    MachinePlan plan = ProfileCutterModule().plan(job, "", PlanOptions{});
    ASSERT_FALSE(plan.outcome.ok());
    EXPECT_EQ(plan.outcome.key, "process.lead_in.length_mm");
    std::printf("refusal: %s\n", plan.outcome.message.c_str());
    EXPECT_NE(plan.outcome.message.find("process.lead_in.length_mm = 100 mm is too long for the "
                                        "hole"),
              std::string::npos);
    double limit = 0;
    const size_t at = plan.outcome.message.find("the longest that fits is ");
    ASSERT_NE(at, std::string::npos);
    std::sscanf(plan.outcome.message.c_str() + at + 25, "%lf", &limit);
    EXPECT_GT(limit, 5);
    EXPECT_LT(limit, 2 * job.branch_pipe.radius_mm);
    // The limit stated fits; a little more does not.
    job.process.lead_in.length_mm = limit - 0.01;
    EXPECT_TRUE(ProfileCutterModule().plan(job, "", PlanOptions{}).outcome.ok());
    job.process.lead_in.length_mm = limit + 0.05;
    EXPECT_FALSE(ProfileCutterModule().plan(job, "", PlanOptions{}).outcome.ok());

    // The lead-out too.
    job = leadJob(CutTarget::Main);
    job.process.lead_out.length_mm = 100;
    plan = ProfileCutterModule().plan(job, "", PlanOptions{});
    EXPECT_EQ(plan.outcome.key, "process.lead_out.length_mm");

    // No pierce height (the shipped charts give none): validate and plan name the override.
    job = leadJob(CutTarget::Main);
    job.process.override.figures[static_cast<size_t>(CutFigure::PierceHeightMm)].reset();
    auto issues = issuesAt(job, "process.override.pierce_height_mm");
    ASSERT_EQ(issues.size(), 1u);
    std::printf("issue: %s\n", issues[0].message.c_str());
    EXPECT_NE(issues[0].message.find("process.lead_in.kind = \"arc\" needs the pierce height"),
              std::string::npos);
    EXPECT_NE(issues[0].message.find("[0, 50] mm"), std::string::npos);
    plan = ProfileCutterModule().plan(job, "", PlanOptions{});
    EXPECT_EQ(plan.outcome.key, "process.override.pierce_height_mm");
    job.process.override.set(CutFigure::PierceHeightMm, 3.8);
    job.process.override.figures[static_cast<size_t>(CutFigure::CutHeightMm)].reset();
    EXPECT_EQ(issuesAt(job, "process.override.cut_height_mm").size(), 1u);

    // An overlap alone (no lead) without the heights: refused naming the override (the plan
    // read an empty figure before).
    job = leadJob(CutTarget::Main);
    job.process.lead_in = {};
    job.process.lead_out = {LeadKind::None, 0, 1.5};
    job.process.override.figures[static_cast<size_t>(CutFigure::PierceHeightMm)].reset();
    plan = ProfileCutterModule().plan(job, "", PlanOptions{});
    EXPECT_EQ(plan.outcome.key, "process.override.pierce_height_mm");
    EXPECT_NE(plan.outcome.message.find("process.lead_out.overlap_mm = 1.5 mm"), std::string::npos)
        << plan.outcome.message;
    job.process.override.set(CutFigure::PierceHeightMm, 3.8);
    EXPECT_TRUE(ProfileCutterModule().plan(job, "", PlanOptions{}).outcome.ok());

    // Lengths out of range.
    job = leadJob(CutTarget::Branch);
    job.process.lead_in.length_mm = 0;
    issues = issuesAt(job, "process.lead_in.length_mm");
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].message, "process.lead_in.length_mm = 0 mm is outside [0.1, 100] mm");
    job.process.lead_out.overlap_mm = 80;
    EXPECT_EQ(issuesAt(job, "process.lead_out.overlap_mm").size(), 1u);

    // Reading: unknown keys and kinds are refused naming the key.
    const std::string base = json::write(jobToJson(leadJob(CutTarget::Branch)));
    auto refusal = [&](const std::string& from, const std::string& to) {
        std::string text = base;
        const size_t p = text.find(from);
        EXPECT_NE(p, std::string::npos) << from;
        if (p == std::string::npos) return std::string();
        text.replace(p, from.size(), to);
        try {
            parseJob(text);
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    std::string e = refusal("\"kind\": \"arc\"", "\"kind\": \"spiral\"");
    std::printf("reading: %s\n", e.c_str());
    EXPECT_NE(e.find("lead_in.kind"), std::string::npos) << e;
    EXPECT_NE(e.find("\"spiral\""), std::string::npos) << e;
    e = refusal("\"kind\": \"arc\"", "\"kind\": \"arc\", \"radius_mm\": 3");
    std::printf("reading: %s\n", e.c_str());
    EXPECT_NE(e.find("radius_mm"), std::string::npos) << e;
    e = refusal("\"kind\": \"arc\",", "");
    EXPECT_NE(e.find("lead_in.kind is required"), std::string::npos) << e;
}

TEST(ProfileLead, KeysRoundTrip) {
    const Job job = leadJob(CutTarget::Main);
    const std::string text = json::write(jobToJson(job));
    EXPECT_NE(text.find("\"lead_in\""), std::string::npos);
    EXPECT_NE(text.find("\"overlap_mm\""), std::string::npos);
    const Job back = parseJob(text);
    EXPECT_EQ(back.process, job.process);
    EXPECT_EQ(json::write(jobToJson(back)), text);
    // The example job ships the keys and plans.
    const Job example = loadJobFile(std::string(CUTCELL_SOURCE_DIR) +
                                    "/resources/jobs/profile_cutter_lead_in_job.json");
    EXPECT_TRUE(example.process.lead_in.used());
    EXPECT_TRUE(validateJob(example).empty());
    MachinePlan plan;
    EXPECT_NE(planGcode(example, &plan).find("(lead-in)"), std::string::npos);
    std::printf("example plan: %s\n", plan.summary.c_str());
}

} // namespace
} // namespace cutcell
