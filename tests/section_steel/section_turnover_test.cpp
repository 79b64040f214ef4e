// Setup 2 (end_cut.setup = 2): the section turned over 180 deg about its long axis so that the
// K groove's bevel on the face that lay on the conveyor can be cut. The turned outline is the
// section rotated (asymmetric U and L included); the bevels of setups 1 and 2 together cover
// both sides of both flanges of a K-grooved mitred IPE end, each tilted by the groove angle in
// the plane normal to the cut edge and meeting the bar's cut plane at the groove depth; a
// setup 2 with nothing to cut is refused naming the key; the key round-trips through the job
// file, under a German locale too.
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/machines/section_steel/end_cut_path.h"
#include "core/machines/section_steel/section_steel_module.h"
#include "core/machines/section_steel/section_steel_planner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <clocale>
#include <cmath>
#include <map>

using namespace cutcell;
using namespace cutcell::section_steel;

namespace {

const MachineModule& steel() {
    const MachineModule* m = findMachine(kSectionSteelId);
    if (!m) throw std::runtime_error("not registered");
    return *m;
}

// The turnover, 180 deg about the bar's axis at mid-height (its own inverse).
Vec3 turnPoint(const Vec3& p, double h) {
    return {p.x(), -p.y(), h - p.z()};
}
Vec3 turnVector(const Vec3& v) {
    return {v.x(), -v.y(), -v.z()};
}

// The torch tilt measured in the plane normal to the cut edge, from the untilted direction
// t0 towards the cut plane's normal m (as in section_path_test.cpp).
double measuredTilt(const Vec3& t, const Vec3& edge, const Vec3& t0, const Vec3& m) {
    const Vec3 normalPart = t - t.dot(edge) * edge;
    const Vec3 side = edge.cross(t0);
    return std::atan2(normalPart.dot(side) * (side.dot(m) > 0 ? 1 : -1), normalPart.dot(t0));
}

Job kGroovedJob() {
    Job job = steel().defaultJob();
    auto* s = job.machine_spec.as<SectionSteelSpec>();
    s->cut = {20, -10, {GrooveType::K, 35, 2}, {GrooveType::K, 30, 2}};
    return job;
}

} // namespace

// Turned over, each straight face of the outline lies on the rotated face of the same name
// (same direction: a rotation keeps the outline counter-clockwise), the former table face on
// top over the full width, and the area is the section's (an L's outline ends with the toe
// radius r2 of its foot, now on the table). UPN: the web goes to +y; L: the vertical leg.
TEST(SectionTurnover, TurnedOutlineIsTheSectionRotatedAboutItsLongAxis) {
    for (const char* name :
         {"IPE 300", "HEB 200", "UPN 200", "UPE 160", "L 120x80x10", "L 100x100x10"}) {
        const auto d = findSection(name);
        ASSERT_TRUE(d) << name;
        const double h = d->h_mm, b = d->b_mm;
        const SectionOutline up(*d), turned(*d, true);
        EXPECT_TRUE(turned.turnedOver());
        std::map<std::string, const OutlineSegment*> byName;
        for (const auto& g : up.segments())
            byName[g.name] = &g;
        int tableFaces = 0;
        for (size_t i = 0; i < turned.segments().size(); ++i) {
            const OutlineSegment& g = turned.segments()[i];
            if (i > 0) {
                EXPECT_LT((g.p0 - turned.segments()[i - 1].p1).norm(), 1e-9) << name << " " << i;
            }
            if (g.arc) continue;
            Vec2 a, c; // the face in setup 1, rotated
            if (g.former_table_face) {
                ++tableFaces;
                a = {-b / 2, 0};
                c = {b / 2, 0};
            } else {
                ASSERT_TRUE(byName.count(g.name)) << name << ": " << g.name;
                a = byName[g.name]->p0;
                c = byName[g.name]->p1;
            }
            const Vec2 ra(-a.x(), h - a.y()), rc(-c.x(), h - c.y());
            const Vec2 dir = (rc - ra).normalized();
            for (const Vec2& q : {g.p0, g.p1}) {
                const Vec2 w = q - ra;
                EXPECT_LT(std::fabs(w.x() * dir.y() - w.y() * dir.x()), 1e-9)
                    << name << " " << g.name;
            }
            EXPECT_GT((g.p1 - g.p0).normalized().dot(dir), 1 - 1e-12) << name << " " << g.name;
        }
        EXPECT_EQ(tableFaces, 1) << name;
        // The former underside is on top, full width.
        for (const auto& g : turned.segments())
            if (g.former_table_face) {
                EXPECT_NEAR(g.p0.y(), h, 1e-12) << name;
                EXPECT_NEAR(g.length, b, 1e-9) << name;
                EXPECT_EQ(g.kind, FaceKind::Flange) << name;
            }
        EXPECT_NEAR(turned.area(), up.area(), 1e-9) << name;
        // What is up changes for the asymmetric sections: the channel's web back, the angle's
        // vertical leg go from -y to +y.
        if (d->family != SectionFamily::I)
            for (const auto& g : turned.segments())
                if (g.name == "web, outer face" || g.name == "vertical leg, outer face") {
                    EXPECT_NEAR(g.p0.x(), b / 2, 1e-12) << name;
                    EXPECT_NEAR(g.p1.x(), b / 2, 1e-12) << name;
                }
    }
}

// The acceptance of the turnover: a K-grooved end of an IPE 300 mitred about both axes.
// Setup 1 cuts the end and five bevels, setup 2 (turned over) only the underside of the bottom
// flange; mapped back onto the bar, the full-tilt bevels cover both faces of both flanges over
// their flat width (less the blend at the ends), every torch tilted by the groove angle in the
// plane normal to the cut edge, every setup-2 tip on the turned section's surface, and every
// bevel meeting the bar's own cut plane at the K groove's depth (T - c) / 2.
TEST(SectionTurnover, KGroovedMitredIpeEndBevelsBothSidesOfBothFlangesInTwoSetups) {
    const Job job = kGroovedJob();
    SectionSteelSpec s = *job.machine_spec.as<SectionSteelSpec>();
    const SectionDims& d = s.section;
    const double h = d.h_mm, b = d.b_mm, tf = d.tf_mm, tw = d.tw_mm, r = d.r_mm;
    const double beta = deg2rad(s.cut.flanges.angle_deg);
    const double depth = (tf - s.cut.flanges.root_face_mm) / 2;
    const EndCut bar(s); // setup 1: the bar's frame
    const Vec3 mBar = bar.planeNormal();

    // Full-tilt bevel points on the flanges per face (z of the face in the bar's frame), y.
    std::map<double, std::vector<double>> covered;
    int setup2Points = 0;
    for (int setup : {1, 2}) {
        s.cut.setup = setup;
        const SteelPlan plan = planEndCut(s);
        ASSERT_TRUE(plan.ok) << "setup " << setup << ": " << plan.problem;
        EXPECT_LE(plan.max_torch_error_mm, 1e-6) << "setup " << setup;
        const EndCut cut(s);
        const Vec3 m = cut.planeNormal();
        EXPECT_EQ(cut.turnedOver(), setup == 2);
        if (setup == 2) {
            ASSERT_EQ(plan.passes.size(), 1u) << "setup 2 cuts only the missing bevel";
            EXPECT_TRUE(plan.passes[0].groove_arm);
            EXPECT_NE(plan.passes[0].name.find("bottom flange, underside"), std::string::npos)
                << plan.passes[0].name;
        } else {
            EXPECT_EQ(plan.passes.front().name, "square");
        }
        for (const auto& pass : plan.passes) {
            if (!pass.groove_arm) continue;
            for (const auto& t : pass.samples) {
                // On the (turned) section's surface, tilted in the plane normal to the edge.
                EXPECT_LT(cut.outline().distanceToOutline({t.p.y(), t.p.z()}), 1e-9);
                EXPECT_NEAR(measuredTilt(t.t, t.edge, t.t0, m), t.tilt_rad, 1e-12);
                const GrooveSpec* gs = cut.grooveOf(t.segment);
                ASSERT_TRUE(gs) << pass.name;
                if (std::fabs(t.tilt_rad - deg2rad(gs->angle_deg)) > 1e-12) continue;
                if (cut.outline().segments()[t.segment].kind != FaceKind::Flange) continue;
                // Back onto the bar: setup 2's frame turned back.
                const Vec3 p = setup == 2 ? turnPoint(t.p, h) : t.p;
                const Vec3 dir = setup == 2 ? turnVector(t.t) : t.t;
                const Vec3 t0 = setup == 2 ? turnVector(t.t0) : t.t0;
                const Vec3 edge = setup == 2 ? turnVector(t.edge) : t.edge;
                if (setup == 2) {
                    ++setup2Points;
                    EXPECT_NEAR(t.p.z(), h, 1e-9); // on top of the turned section
                    EXPECT_NEAR(p.z(), 0, 1e-9);   // = the bar's underside
                    EXPECT_GT(t0.z(), 0.5);        // into the flange from below
                }
                // The tilt, measured on the bar against the bar's cut plane.
                EXPECT_NEAR(measuredTilt(dir, edge, t0, mBar), beta, 1e-12);
                // The bevel meets the bar's cut plane at the groove depth below its face.
                const double toPlane =
                    (bar.planeX(p.y(), p.z()) - p.x()) * mBar.x() / dir.dot(mBar);
                const Vec3 hit = p + toPlane * dir;
                EXPECT_NEAR(hit.x(), bar.planeX(hit.y(), hit.z()), 1e-9);
                EXPECT_NEAR((hit - p).dot(t0), depth, 1e-9);
                // Coverage along the edge: the outline point (the tip is offset in the face
                // by the bevel, across a mitred edge), turned back.
                const double yBar = setup == 2 ? -t.yz.x() : t.yz.x();
                const double zBar = setup == 2 ? h - t.yz.y() : t.yz.y();
                covered[std::round(zBar * 1e6) / 1e6].push_back(yBar);
            }
        }
    }
    EXPECT_GT(setup2Points, 50);
    // Both faces of both flanges: [y0, y1] flat stretches of each face, less the blend.
    const double blend = s.blend_mm, step = s.knot_spacing_mm;
    const struct Face {
        double z, y0, y1;
    } faces[] = {{0, -b / 2, b / 2},          {tf, -b / 2, -tw / 2 - r},
                 {tf, tw / 2 + r, b / 2},     {h - tf, -b / 2, -tw / 2 - r},
                 {h - tf, tw / 2 + r, b / 2}, {h, -b / 2, b / 2}};
    for (const Face& f : faces) {
        std::vector<double> ys;
        for (double y : covered[f.z])
            if (y >= f.y0 && y <= f.y1) ys.push_back(y);
        ASSERT_FALSE(ys.empty()) << "no full bevel on the face z = " << f.z << " from " << f.y0;
        std::sort(ys.begin(), ys.end());
        EXPECT_LE(ys.front(), f.y0 + blend + step) << "face z = " << f.z;
        EXPECT_GE(ys.back(), f.y1 - blend - step) << "face z = " << f.z;
        double gap = 0;
        for (size_t i = 1; i < ys.size(); ++i)
            gap = std::max(gap, ys[i] - ys[i - 1]);
        EXPECT_LE(gap, step + 1e-9) << "face z = " << f.z;
    }
    // Through the module: setup 1 tells the operator to turn the section over, setup 2 says
    // what it is.
    const MachinePlan one = steel().plan(job, {});
    ASSERT_TRUE(one.ok()) << one.outcome.message;
    EXPECT_NE(one.summary.find("turn the section over"), std::string::npos) << one.summary;
    EXPECT_NE(one.summary.find("end_cut.setup = 2"), std::string::npos) << one.summary;
    Job two = job;
    two.machine_spec.as<SectionSteelSpec>()->cut.setup = 2;
    EXPECT_TRUE(steel().validate(two).empty());
    const MachinePlan p2 = steel().plan(two, {});
    ASSERT_TRUE(p2.ok()) << p2.outcome.message;
    EXPECT_EQ(p2.summary.rfind("setup 2 of 2", 0), 0u) << p2.summary;
    EXPECT_EQ(p2.summary.find("turn the section over"), std::string::npos) << p2.summary;
}

// The channels and angles turn over differently (asymmetric): their setup 2 plans the bevel
// on the turned section's top face, reachable and clear of the torch body, for the default
// cell, square and mitred.
TEST(SectionTurnover, ChannelsAndAnglesPlanTheirSecondSetup) {
    for (const char* name : {"UPN 200", "UPE 200", "L 120x80x10", "L 100x100x10", "HEA 300"}) {
        for (double mitre : {0.0, 20.0}) {
            SectionSteelSpec s = defaultSectionSteelSpec();
            s.section = *findSection(name);
            s.cut = {mitre, -mitre / 2, {GrooveType::K, 30, 2}, {GrooveType::None, 30, 0}, 2};
            const SteelPlan p = planEndCut(s);
            EXPECT_TRUE(p.ok) << name << " mitre " << mitre << ": " << p.problem;
            if (!p.ok) continue;
            ASSERT_EQ(p.passes.size(), 1u) << name;
            const EndCut cut(s);
            for (const auto& t : p.passes[0].samples) {
                EXPECT_NEAR(t.p.z(), s.section.h_mm, 1e-9) << name;
                EXPECT_FALSE(torchHit(cut, cut.torchBody(), t.p, t.t, false)) << name;
            }
        }
    }
}

// Every catalogue entry with K-grooved flanges plans its setup 2, square and mitred both ways.
TEST(SectionTurnover, EveryCatalogueEntryPlansItsSecondSetup) {
    int total = 0, ok = 0;
    for (const auto& d : sectionCatalogue())
        for (double mitre : {0.0, 30.0, -30.0}) {
            SectionSteelSpec s = defaultSectionSteelSpec();
            s.section = d;
            s.cut = {mitre, mitre / 2, {GrooveType::K, 30, 2}, {GrooveType::K, 30, 2}, 2};
            const SteelPlan p = planEndCut(s);
            ++total;
            ok += p.ok;
            EXPECT_TRUE(p.ok) << d.designation << " mitre " << mitre << ": " << p.problem;
            EXPECT_LE(p.max_torch_error_mm, 1e-6) << d.designation;
        }
    std::printf("setup 2 (turned over, K 30 deg on the flanges): %d of %d plan (square, mitred "
                "30/15 and -30/-15 deg, every catalogue entry)\n",
                ok, total);
}

// Setup 2 of a section whose K groove is not on the flanges (V, Y, none; or K on the web only,
// whose both faces setup 1 reaches) has nothing to cut: refused naming the key, by the
// validation, the planner and the module, never an empty run.
TEST(SectionTurnover, SetupTwoWithNothingLeftIsRefusedNamingTheKey) {
    for (GrooveType g : {GrooveType::V, GrooveType::Y, GrooveType::None}) {
        Job job = steel().defaultJob();
        auto* s = job.machine_spec.as<SectionSteelSpec>();
        s->cut.flanges = {g, 30, g == GrooveType::Y ? 2.0 : 0.0};
        s->cut.web = {GrooveType::K, 30, 2};
        s->cut.setup = 2;
        const std::string want = std::string("end_cut.flanges.groove = \"") + toString(g) + "\"";
        const auto issues = steel().validate(job);
        ASSERT_EQ(issues.size(), 1u);
        EXPECT_EQ(issues[0].key, "end_cut.setup");
        EXPECT_NE(issues[0].message.find("end_cut.setup = 2"), std::string::npos)
            << issues[0].message;
        EXPECT_NE(issues[0].message.find("nothing is left to cut"), std::string::npos);
        EXPECT_NE(issues[0].message.find(want), std::string::npos) << issues[0].message;
        const SteelPlan p = planEndCut(*s);
        EXPECT_FALSE(p.ok);
        EXPECT_EQ(p.problem, issues[0].message);
        const MachinePlan mp = steel().plan(job, {});
        EXPECT_FALSE(mp.ok());
        EXPECT_FALSE(mp.program);
        EXPECT_EQ(mp.outcome.message, issues[0].message);
    }
    // An angle names its horizontal leg.
    SectionSteelSpec l = defaultSectionSteelSpec();
    l.section = *findSection("L 120x80x10");
    l.cut.setup = 2;
    EXPECT_NE(setupTwoProblem(l).find("underside of the horizontal leg"), std::string::npos)
        << setupTwoProblem(l);
    l.cut.setup = 1;
    EXPECT_EQ(setupTwoProblem(l), "");
}

// end_cut.setup round-trips through the job file; a job written before it existed loads as
// setup 1; other values are refused with the key, the value and the range.
TEST(SectionTurnover, SetupKeyRoundTripsAndIsValidated) {
    const Job job = kGroovedJob();
    Job two = job;
    two.machine_spec.as<SectionSteelSpec>()->cut.setup = 2;
    const std::string text = json::write(jobToJson(two));
    EXPECT_NE(text.find("\"setup\": 2"), std::string::npos);
    const Job back = parseJob(text);
    EXPECT_EQ(back.machine_spec.as<SectionSteelSpec>()->cut.setup, 2);
    EXPECT_EQ(json::write(jobToJson(back)), text);
    // Older files (no setup key) load as setup 1.
    const std::string one = json::write(jobToJson(job));
    const std::string key = "\"setup\": 1";
    const size_t at = one.find(key);
    ASSERT_NE(at, std::string::npos);
    std::string old = one;
    const size_t comma = old.rfind(',', at);
    old.erase(comma, at + key.size() - comma);
    EXPECT_EQ(old.find("\"setup\""), std::string::npos);
    EXPECT_EQ(parseJob(old).machine_spec.as<SectionSteelSpec>()->cut.setup, 1);
    for (const char* bad : {"3", "0", "1.5", "-1", "\"2\"", "true"}) {
        std::string t = one;
        t.replace(at, key.size(), std::string("\"setup\": ") + bad);
        try {
            parseJob(t);
            ADD_FAILURE() << "accepted setup " << bad;
        } catch (const JobError& e) {
            const std::string w = e.what();
            EXPECT_NE(w.find("machine.end_cut.setup = "), std::string::npos) << w;
            EXPECT_NE(w.find("range [1, 2]"), std::string::npos) << w;
        }
    }
    Job wrong = job;
    wrong.machine_spec.as<SectionSteelSpec>()->cut.setup = 7;
    const auto issues = steel().validate(wrong);
    ASSERT_FALSE(issues.empty());
    EXPECT_EQ(issues[0].message, "end_cut.setup = 7 is outside [1, 2]");
}

// A decimal-comma locale changes neither the job file with the key nor the plan's summary.
TEST(SectionTurnover, GermanLocaleChangesNeitherTheFileNorTheSummary) {
    Job job = kGroovedJob();
    job.machine_spec.as<SectionSteelSpec>()->cut.flanges.angle_deg = 37.5;
    job.machine_spec.as<SectionSteelSpec>()->cut.setup = 2;
    const std::string text = json::write(jobToJson(job));
    const std::string summary = steel().plan(job, {}).summary;
    const std::string saved = std::setlocale(LC_ALL, nullptr);
    if (!std::setlocale(LC_ALL, "de_DE.UTF-8")) GTEST_SKIP() << "locale de_DE.UTF-8 missing";
    const std::string germanText = json::write(jobToJson(job));
    const Job back = parseJob(text);
    const std::string germanSummary = steel().plan(back, {}).summary;
    std::setlocale(LC_ALL, saved.c_str());
    EXPECT_EQ(germanText, text);
    EXPECT_EQ(back.machine_spec.as<SectionSteelSpec>()->cut.setup, 2);
    EXPECT_EQ(back.machine_spec.as<SectionSteelSpec>()->cut.flanges.angle_deg, 37.5);
    EXPECT_EQ(germanSummary, summary);
    EXPECT_NE(summary.find("-20.0/10.0 deg"), std::string::npos) << summary;
}
