// The profile catalogue and the torch path of an end cut: every catalogue entry draws and
// plans; the path lies on the section's surface (the bevel offset in the face); the torch tilt
// equals the groove angle in the plane normal to the cut edge; torch-body collisions reported.
#include "core/machines/section_steel/end_cut_path.h"
#include "core/machines/section_steel/section_steel_planner.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace cutcell;
using namespace cutcell::section_steel;

TEST(SectionCatalogue, FamiliesAndLookup) {
    const auto& c = sectionCatalogue();
    int I = 0, U = 0, L = 0;
    for (const auto& d : c) {
        I += d.family == SectionFamily::I;
        U += d.family == SectionFamily::U;
        L += d.family == SectionFamily::L;
        EXPECT_LT(d.tf_mm, d.h_mm / 2) << d.designation;
        EXPECT_LT(d.tw_mm, d.b_mm) << d.designation;
    }
    EXPECT_GE(I, 50);
    EXPECT_GE(U, 20);
    EXPECT_GE(L, 15);
    ASSERT_TRUE(findSection("ipe300"));
    EXPECT_EQ(findSection("IPE 300")->h_mm, 300);
    EXPECT_FALSE(findSection("IPE 301"));
    EXPECT_THROW(parseSectionCatalogue("I,IPE 1,80,46,3,8,5.2,5\n"), std::runtime_error);
    EXPECT_THROW(parseSectionCatalogue("# c\nI,IPE 1,80,4x6,3.8,5.2,5,0,0,7.6\n"),
                 std::runtime_error);
    EXPECT_THROW(parseSectionCatalogue("I,IPE 1,80,46,3.8,5.2,5,-1,0,7.6\n"), std::runtime_error);
    EXPECT_EQ(parseSectionCatalogue("I,IPE 1,80,46,3.8,5.2,5,0,0,7.6\n").at(0).area_cm2, 7.6);
}

// The drawn outline (h, b, tw, tf, r1, r2; UPN flanges at their equal-area thickness) against
// the area tabulated in EN 10365 / EN 10056-1 (3 significant digits): within 1 %. A wrong h, b,
// tw, tf or r in a row shows here (1 mm of tf on an IPE 300 is 5.6 % of its area).
TEST(SectionCatalogue, OutlineAreaMatchesTheStandardsTable) {
    double worst = 0;
    std::string worstName;
    for (const auto& d : sectionCatalogue()) {
        ASSERT_GT(d.area_cm2, 0) << d.designation;
        const double drawn = SectionOutline(d).area() / 100; // cm^2
        const double rel = std::fabs(drawn - d.area_cm2) / d.area_cm2;
        EXPECT_LT(rel, 0.01) << d.designation << ": drawn " << drawn << " cm2, table " << d.area_cm2
                             << " cm2";
        if (rel > worst) {
            worst = rel;
            worstName = d.designation;
        }
    }
    std::printf("outline area against the standard's table: worst %.2f %% (%s)\n", 100 * worst,
                worstName.c_str());
    // The exact area of a plain I section: 2 b tf + (h - 2 tf) tw + (4 - pi) r^2.
    const SectionDims ipe = *findSection("IPE 300");
    EXPECT_NEAR(SectionOutline(ipe).area(),
                2 * ipe.b_mm * ipe.tf_mm + (ipe.h_mm - 2 * ipe.tf_mm) * ipe.tw_mm +
                    (4 - kPi) * ipe.r_mm * ipe.r_mm,
                1e-9);
}

TEST(SectionOutline, EveryEntryIsAClosedOutlineOfTheRightLength) {
    for (const auto& d : sectionCatalogue()) {
        const SectionOutline o(d);
        EXPECT_TRUE(checkSectionDims(d, "section").empty()) << d.designation;
        // Continuity: each segment starts where the previous one ends.
        for (size_t i = 1; i < o.segments().size(); ++i)
            EXPECT_LT((o.segments()[i].p0 - o.segments()[i - 1].p1).norm(), 1e-9)
                << d.designation << " segment " << i;
        // The perimeter of the outline plus the table face equals the polygon perimeter
        // computed independently for I sections: 2h + 4b - 2tw + (2 pi - 8) r ... check the
        // simpler property that every sampled point is on the outline and outside the material.
        for (double s = 0; s <= o.length(); s += o.length() / 200) {
            const OutlinePoint p = o.at(s);
            EXPECT_LT(o.distanceToOutline(p.p), 1e-9) << d.designation;
            EXPECT_FALSE(o.contains(p.p + 0.5 * p.normal)) << d.designation << " s " << s;
            EXPECT_TRUE(o.contains(p.p - 0.5 * p.normal) || p.p.y() < 0.6)
                << d.designation << " s " << s;
        }
    }
}

// The default IPE 300 with bevels: V on the flanges, then mitred both ways with K grooves.
// Every point reached inside the limits by the arm that cuts it, the torch where planned.
TEST(EndCutPlan, GroovedEndPlans) {
    SectionSteelSpec s = defaultSectionSteelSpec();
    s.cut.flanges = {GrooveType::V, 30, 0};
    const SteelPlan p = planEndCut(s);
    ASSERT_TRUE(p.ok) << p.problem;
    EXPECT_LE(p.max_torch_error_mm, 1e-6);
    EXPECT_GE(p.passes.size(), 4u); // square + top flange + two bottom flange halves
    s.cut = {30, -20, {GrooveType::K, 45, 2}, {GrooveType::K, 35, 2}};
    const SteelPlan k = planEndCut(s);
    ASSERT_TRUE(k.ok) << k.problem;
    EXPECT_LE(k.max_torch_error_mm, 1e-6);
    // Both faces of the web are bevelled (K).
    int webPasses = 0;
    for (const auto& pass : k.passes)
        webPasses += pass.name.rfind("groove web", 0) == 0;
    EXPECT_EQ(webPasses, 2);
}

TEST(EndCutPath, OnTheSurfaceAndTiltEqualsTheGrooveAngle) {
    for (double mitre : {0.0, 20.0}) {
        for (GrooveType g : {GrooveType::V, GrooveType::Y, GrooveType::K}) {
            SectionSteelSpec s = defaultSectionSteelSpec();
            s.cut.mitre_vertical_deg = mitre;
            s.cut.mitre_horizontal_deg = mitre / 2;
            s.cut.flanges = {g, 30, g == GrooveType::V ? 0.0 : 2.0};
            s.cut.web = {g, 25, g == GrooveType::V ? 0.0 : 2.0};
            const EndCut cut(s);
            const Vec3 m = cut.planeNormal();
            const auto passes = cut.passes(0.2);
            ASSERT_GE(passes.size(), 2u);
            int fullTilt = 0;
            for (const auto& pass : passes)
                for (const auto& t : pass.samples) {
                    // On the section's surface: (y, z) on the outline.
                    EXPECT_LT(cut.outline().distanceToOutline({t.p.y(), t.p.z()}), 1e-9);
                    // Without a bevel the tip is in the cut plane; with one it is on the kept
                    // side, D tan(beta) away from it.
                    const double off = t.p.x() - cut.planeX(t.p.y(), t.p.z());
                    if (t.tilt_rad == 0)
                        EXPECT_NEAR(off, 0, 1e-9);
                    else
                        EXPECT_LT(off * m.x(), 0);
                    // Torch, edge and t0: unit; the torch leans along the edge by lean_rad
                    // (where its body needs room), the tilt is measured in the plane normal to
                    // the edge from the untilted direction, so the cut face does not change.
                    EXPECT_NEAR(t.t.norm(), 1, 1e-12);
                    EXPECT_NEAR(t.t.dot(t.edge), std::sin(t.lean_rad), 1e-12);
                    EXPECT_LE(std::fabs(t.lean_rad), deg2rad(s.max_lean_deg) + 1e-12);
                    EXPECT_NEAR(t.t0.dot(t.edge), 0, 1e-12);
                    EXPECT_NEAR(t.t0.dot(m), 0, 1e-12);
                    const Vec3 normalPart = t.t - t.t.dot(t.edge) * t.edge;
                    const double measured = std::atan2(normalPart.dot(t.edge.cross(t.t0)) *
                                                           (t.edge.cross(t.t0).dot(m) > 0 ? 1 : -1),
                                                       normalPart.dot(t.t0));
                    EXPECT_NEAR(measured, t.tilt_rad, 1e-12);
                    const GrooveSpec* gs = cut.grooveOf(t.segment);
                    if (gs && std::fabs(t.tilt_rad - deg2rad(gs->angle_deg)) < 1e-12) ++fullTilt;
                    if (!gs) {
                        EXPECT_EQ(t.tilt_rad, 0);
                    }
                }
            EXPECT_GT(fullTilt, 100) << "the groove angle is reached on the bevelled faces";
        }
    }
}

TEST(EndCutPath, BevelMeetsTheCutPlaneAtTheGrooveDepth) {
    SectionSteelSpec s = defaultSectionSteelSpec();
    s.cut.flanges = {GrooveType::Y, 30, 3};
    const EndCut cut(s);
    const auto passes = cut.passes(0.2);
    const Vec3 m = cut.planeNormal();
    int checked = 0;
    for (const auto& t : passes[2].samples) {
        const GrooveSpec* gs = cut.grooveOf(t.segment);
        if (!gs || std::fabs(t.tilt_rad - deg2rad(30)) > 1e-12) continue;
        // Along the torch from the tip to the cut plane: the depth below the face is T - c.
        const double toPlane = -(t.p.x() - cut.planeX(t.p.y(), t.p.z())) / t.t.dot(m) * m.x();
        const Vec3 hit = t.p + toPlane * t.t;
        EXPECT_NEAR(hit.x(), cut.planeX(hit.y(), hit.z()), 1e-9);
        const double T = cut.outline().segments()[t.segment].thickness_mm;
        EXPECT_NEAR((hit - t.p).dot(t.t0), T - 3, 1e-9);
        ++checked;
    }
    EXPECT_GT(checked, 10);
}

// Every catalogue entry plans a square end and a grooved end mitred about both axes (V on the
// flanges, Y on the web, 30/15 deg), and a K-grooved end mitred the other way.
TEST(EndCutPlan, EveryCatalogueEntryPlansASquareAndAGroovedMitredEnd) {
    int square = 0, grooved = 0, kGrooved = 0, total = 0;
    for (const auto& d : sectionCatalogue()) {
        ++total;
        SectionSteelSpec s = defaultSectionSteelSpec();
        s.section = d;
        const SteelPlan p = planEndCut(s);
        EXPECT_TRUE(p.ok) << d.designation << " square: " << p.problem;
        EXPECT_LE(p.max_torch_error_mm, 1e-6) << d.designation;
        square += p.ok;
        s.cut = {30, 15, {GrooveType::V, 30, 0}, {GrooveType::Y, 30, 2}};
        const SteelPlan g = planEndCut(s);
        EXPECT_TRUE(g.ok) << d.designation << " V/Y mitred 30/15: " << g.problem;
        EXPECT_LE(g.max_torch_error_mm, 1e-6) << d.designation;
        EXPECT_GE(g.passes.size(), 3u) << d.designation;
        grooved += g.ok;
        s.cut = {-30, -15, {GrooveType::K, 30, 2}, {GrooveType::K, 30, 2}};
        const SteelPlan k = planEndCut(s);
        EXPECT_TRUE(k.ok) << d.designation << " K mitred -30/-15: " << k.problem;
        kGrooved += k.ok;
    }
    std::printf("of %d catalogue entries: %d plan a square end, %d a V/Y end mitred 30/15 deg, "
                "%d a K end mitred -30/-15 deg\n",
                total, square, grooved, kGrooved);
}

TEST(EndCutPlan, TorchBodyCollisionIsReported) {
    SectionSteelSpec s = defaultSectionSteelSpec();
    s.section = *findSection("IPE 100"); // 88.6 mm between the flanges
    s.torch_length_mm = 150;
    s.max_lean_deg = 0; // the torch normal to every face: it hits the other flange
    const SteelPlan p = planEndCut(s);
    EXPECT_FALSE(p.ok);
    EXPECT_NE(p.problem.find("torch body hits the section"), std::string::npos) << p.problem;
    EXPECT_NE(p.problem.find("point "), std::string::npos) << p.problem;
    // Leaning along the cut edge (in the kerf plane) it clears: every point checked clear.
    s.max_lean_deg = 45;
    const SteelPlan leaned = planEndCut(s);
    EXPECT_TRUE(leaned.ok) << leaned.problem;
    const EndCut cut(s);
    double maxLean = 0;
    for (const auto& pass : leaned.passes)
        for (const auto& t : pass.samples) {
            EXPECT_FALSE(torchHit(cut, cut.torchBody(), t.p, t.t, pass.name == "square"));
            maxLean = std::max(maxLean, std::fabs(t.lean_rad));
        }
    EXPECT_GT(maxLean, 0);
    // Allowed only a small lean it still hits: the status names the lean and its limit.
    s.max_lean_deg = 4;
    const SteelPlan thick = planEndCut(s);
    EXPECT_FALSE(thick.ok);
    EXPECT_NE(thick.problem.find("max_lean_deg = 4)"), std::string::npos) << thick.problem;
}

TEST(EndCutPlan, JointLimitIsNamed) {
    SectionSteelSpec s = defaultSectionSteelSpec();
    s.path_limits[0] = {-100, -80};
    const SteelPlan p = planEndCut(s);
    EXPECT_FALSE(p.ok);
    EXPECT_NE(p.problem.find("path arm joint theta1"), std::string::npos) << p.problem;
    EXPECT_NE(p.problem.find("[-100.0, -80.0] deg"), std::string::npos) << p.problem;
}

// Every catalogue entry plans its square end at the slow and fast ends of the cutting speed the
// job accepts (0.1, 100 mm/s) and at a slow and the fastest torch turn (10, 360 deg/s): the
// joint-jump check scales with both, so a plan that holds at the default speeds only can hide a
// torch turning faster than it may. The torch turns at most reorient_deg_s, at sharp toes (the
// tip at rest) and round toe radii and fillets alike (the tip slows where speed / radius would
// turn it faster): between two samples the untilted direction turns at most reorient * dt.
TEST(EndCutPlan, EveryCatalogueEntryPlansAtTheEndsOfTheSpeedRange) {
    int total = 0, ok = 0;
    for (const double speed : {0.1, 100.0})
        for (const double reorient : {10.0, 360.0})
            for (const auto& d : sectionCatalogue()) {
                SectionSteelSpec s = defaultSectionSteelSpec();
                s.section = d;
                s.speed_mm_s = speed;
                s.reorient_deg_s = reorient;
                const SteelPlan p = planEndCut(s);
                ++total;
                ok += p.ok;
                const std::string at = d.designation + " at " + std::to_string(speed) + " mm/s, " +
                                       std::to_string(reorient) + " deg/s";
                EXPECT_TRUE(p.ok) << at << ": " << p.problem;
                ASSERT_FALSE(p.passes.empty()) << at;
                const CutPass& square = p.passes.front();
                double worst = 0;
                for (size_t k = 1; k < square.samples.size(); ++k) {
                    const Vec3& a = square.samples[k - 1].t0;
                    const Vec3& b = square.samples[k].t0;
                    worst = std::max(worst, std::atan2(a.cross(b).norm(), a.dot(b)));
                }
                EXPECT_LE(worst, deg2rad(reorient) * p.dt * (1 + 1e-9) + 1e-12)
                    << at << ": the torch turns " << rad2deg(worst) << " deg in one step of "
                    << p.dt << " s";
            }
    std::printf("%d of %d (entry, speed, turn rate) square ends plan\n", ok, total);
}
