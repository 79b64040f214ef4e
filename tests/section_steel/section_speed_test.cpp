// Issue 22: the torch keeps the job's cutting speed along the planned end cut, square and
// mitred. The time law is measured on the planned points themselves: between two consecutive
// samples (dt apart) the tip moves |dp| = v dt on the plateau of the speed profile, or, where
// the torch turns (at a sharp toe with the tip at rest, round a radius tighter than v / w),
// the torch turns w dt; the pass's length is the sum of |dp|. Every catalogue entry, mitred
// about both axes, both signs, up to the job's limit (45 deg).
#include "core/machines/section_steel/end_cut_path.h"
#include "core/machines/section_steel/section_steel_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace cutcell;
using namespace cutcell::section_steel;

namespace {

double angleBetween(const Vec3& a, const Vec3& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

struct SpeedFigures {
    double maxSpeed = 0, minSpeed = 1e300; // mm/s, steps at the cutting speed on the plateau
    std::string maxAt, minAt;
    double worstRate = 0; // max |rate - 1| of the steps at the cutting speed or turning
    std::string worstRateAt;
    double worstLength = 0; // max |sum |dp| - length_mm| / length_mm
    std::string worstLengthAt;
    int passes = 0, steps = 0;
};

// Checks one pass (the speed profile of the spec, samples dt apart) and adds to the figures.
void checkPass(const SectionSteelSpec& s, const CutPass& pass, double dt, const std::string& at,
               SpeedFigures& f) {
    const double v = s.speed_mm_s, w = deg2rad(s.reorient_deg_s);
    ASSERT_GE(pass.samples.size(), 3u) << at;
    double sum = 0;
    for (size_t k = 1; k < pass.samples.size(); ++k)
        sum += (pass.samples[k].p - pass.samples[k - 1].p).norm();
    const double lengthError = std::fabs(sum - pass.length_mm) / pass.length_mm;
    // Chords of 2 mm on the radii are a little shorter than the arcs.
    EXPECT_LT(lengthError, 5e-3) << at << ": sum |dp| = " << sum
                                 << " mm, length_mm = " << pass.length_mm;
    if (lengthError > f.worstLength) {
        f.worstLength = lengthError;
        f.worstLengthAt = at;
    }
    // The plateau: both samples past the start ramp and before the stop ramp.
    const double ramp = std::min(s.ramp_s, pass.duration_s);
    // A groove pass's tip path has a corner where the tilt's ramp ends (the bevel's offset
    // grows, then stays): a chord across it is shorter than the path.
    double fullTilt = 0;
    for (const TorchTarget& t : pass.samples)
        fullTilt = std::max(fullTilt, t.tilt_rad);
    ++f.passes;
    int failures = 0;
    for (size_t k = 1; k < pass.samples.size(); ++k) {
        const double t0 = static_cast<double>(k - 1) * dt, t1 = static_cast<double>(k) * dt;
        if (t0 < ramp - 1e-9 || t1 > pass.duration_s - ramp + 1e-9) continue;
        const TorchTarget &a = pass.samples[k - 1], &b = pass.samples[k];
        const double moved = (b.p - a.p).norm() / (v * dt);
        const double turned = angleBetween(a.t0, b.t0) / (w * dt);
        // One stretch: travel along one face (inside or outside the tilt's ramp), or the turn
        // at one corner (the tip at rest, the torch at w).
        const bool travel = !a.turning && !b.turning && a.segment == b.segment &&
                            (a.tilt_rad == fullTilt) == (b.tilt_rad == fullTilt);
        const bool turn = a.turning && b.turning && a.s_mm == b.s_mm;
        // Travel round a radius tighter than v / w: the tip slows, the torch turns at w. A
        // step may hold both, where the curvature of a mitred radius (an ellipse's arc in the
        // cut plane) crosses w / v: the torch turns at more than 3/4 of w over the step.
        const bool slowed = travel && turned > 0.75;
        ++f.steps;
        if (travel || turn) {
            const double rate = turn ? turned : slowed ? std::max(moved, turned) : moved;
            const double tolerance = slowed ? 0.1 : 0.01;
            if (std::fabs(rate - 1) > f.worstRate && !slowed) {
                f.worstRate = std::fabs(rate - 1);
                f.worstRateAt = at + ", " + pass.name + " point " + std::to_string(k);
            }
            if ((std::fabs(rate - 1) > tolerance || moved > 1.01 || turned > 1.01) &&
                failures++ < 3)
                ADD_FAILURE() << at << ", pass " << pass.name << ", point " << k << " ("
                              << (turn     ? "turning"
                                  : slowed ? "slowed"
                                           : "travel")
                              << ", s = " << b.s_mm << " mm): the tip moves " << moved * v
                              << " mm/s for " << v << " mm/s, the torch turns "
                              << rad2deg(turned * w) << " deg/s for " << s.reorient_deg_s
                              << " deg/s";
            if (travel && !slowed) { // the tip at the cutting speed
                const double speed = moved * v;
                if (speed > f.maxSpeed) {
                    f.maxSpeed = speed;
                    f.maxAt = at + ", " + pass.name + " point " + std::to_string(k);
                }
                if (speed < f.minSpeed) {
                    f.minSpeed = speed;
                    f.minAt = at + ", " + pass.name + " point " + std::to_string(k);
                }
            }
        } else if ((moved > 1.01 || turned > 1.01) && failures++ < 3) {
            // From one stretch into the next: neither faster than it may.
            ADD_FAILURE() << at << ", pass " << pass.name << ", point " << k
                          << ": across a face boundary the tip moves " << moved * v
                          << " mm/s, the torch turns " << rad2deg(turned * w) << " deg/s";
        }
    }
}

void print(const char* what, const SpeedFigures& f, double v) {
    std::printf("%s: %d passes, %d steps on the plateau; tip speed %.4f .. %.4f mm/s for %.2f "
                "mm/s (max at %s; min at %s); worst |rate - 1| %.3g %% (%s); worst length "
                "error %.3g %% (%s)\n",
                what, f.passes, f.steps, f.minSpeed, f.maxSpeed, v, f.maxAt.c_str(),
                f.minAt.c_str(), 100 * f.worstRate, f.worstRateAt.c_str(), 100 * f.worstLength,
                f.worstLengthAt.c_str());
}

} // namespace

// The square and mitred cut (the path arm's pass) of every catalogue entry: square, mitred
// about z (vertical) and about y (horizontal), both signs, at 15, 30 and 45 deg, and about
// both at +-45/+-45.
TEST(SectionEndCutSpeed, EveryCatalogueEntryKeepsTheCuttingSpeedOnEveryMitre) {
    struct Mitre {
        double vertical, horizontal;
    };
    std::vector<Mitre> mitres{{0, 0}};
    for (const double a : {15.0, 30.0, 45.0})
        for (const double sign : {1.0, -1.0}) {
            mitres.push_back({sign * a, 0});
            mitres.push_back({0, sign * a});
        }
    for (const double sv : {1.0, -1.0})
        for (const double sh : {1.0, -1.0})
            mitres.push_back({45 * sv, 45 * sh});
    SpeedFigures all;
    const SectionSteelSpec base = defaultSectionSteelSpec();
    for (const auto& d : sectionCatalogue())
        for (const Mitre& m : mitres) {
            SectionSteelSpec s = base;
            s.section = d;
            s.cut.mitre_vertical_deg = m.vertical;
            s.cut.mitre_horizontal_deg = m.horizontal;
            const double dt = s.knot_spacing_mm / s.speed_mm_s; // as planEndCut
            const auto passes = EndCut(s).passes(dt);
            ASSERT_FALSE(passes.empty());
            ASSERT_EQ(passes.front().name, "square");
            char at[96];
            std::snprintf(at, sizeof at, "%s mitre %g/%g deg", d.designation.c_str(), m.vertical,
                          m.horizontal);
            checkPass(s, passes.front(), dt, at, all);
        }
    print("square and mitred end cuts", all, base.speed_mm_s);
    EXPECT_LT(all.maxSpeed, base.speed_mm_s * 1.01);
    EXPECT_GT(all.minSpeed, base.speed_mm_s * 0.99);
}

// The groove arm's passes too: the bevel's tilt ramps in over blend_mm and the tip, D tan(beta)
// behind the cut line, moves across the face as it does; it keeps the cutting speed there.
// At a faster speed and torch turn as well (the ramps and turns scale).
TEST(SectionEndCutSpeed, GroovePassesKeepTheCuttingSpeed) {
    SpeedFigures all;
    for (const char* name : {"IPE 300", "HEB 200", "UPN 300", "UPN 100", "L 100x100x10"}) {
        const auto d = findSection(name);
        ASSERT_TRUE(d) << name;
        for (const double mitre : {0.0, 30.0, -45.0})
            for (const double speed : {5.0, 20.0}) {
                SectionSteelSpec s = defaultSectionSteelSpec();
                s.section = *d;
                s.speed_mm_s = speed;
                s.reorient_deg_s = speed == 5 ? 45 : 180;
                s.cut = {mitre, mitre / 2, {GrooveType::K, 30, 2}, {GrooveType::V, 35, 0}};
                const double dt = s.knot_spacing_mm / s.speed_mm_s;
                const auto passes = EndCut(s).passes(dt);
                ASSERT_GE(passes.size(), 3u) << name;
                for (const CutPass& pass : passes) {
                    char at[96];
                    std::snprintf(at, sizeof at, "%s mitre %g/%g deg at %g mm/s", name, mitre,
                                  mitre / 2, speed);
                    SpeedFigures one;
                    checkPass(s, pass, dt, at, one);
                    all.passes += one.passes;
                    all.steps += one.steps;
                    // The figures in mm/s of the job's speed: compare as rates.
                    if (one.maxSpeed / speed > all.maxSpeed) {
                        all.maxSpeed = one.maxSpeed / speed;
                        all.maxAt = one.maxAt;
                    }
                    if (one.minSpeed / speed < all.minSpeed) {
                        all.minSpeed = one.minSpeed / speed;
                        all.minAt = one.minAt;
                    }
                    if (one.worstRate > all.worstRate) {
                        all.worstRate = one.worstRate;
                        all.worstRateAt = one.worstRateAt;
                    }
                    if (one.worstLength > all.worstLength) {
                        all.worstLength = one.worstLength;
                        all.worstLengthAt = one.worstLengthAt;
                    }
                }
            }
    }
    print("groove passes (speeds as a fraction of the job's)", all, 1);
}

// The plan gives the real length and time: the 3D length of the mitred path, cut at the job's
// speed (plus the ramps and the torch turns); the square cut's figures stay.
TEST(SectionEndCutSpeed, PlanLengthAndTimeAreThoseOfTheMitredPath) {
    SectionSteelSpec s = defaultSectionSteelSpec(); // IPE 300, 5 mm/s
    const SteelPlan square = planEndCut(s);
    ASSERT_TRUE(square.ok) << square.problem;
    EXPECT_NEAR(square.length_mm, 1010.0, 0.05);
    for (const double mitre : {30.0, -30.0}) {
        s.cut.mitre_horizontal_deg = mitre;
        const SteelPlan p = planEndCut(s);
        ASSERT_TRUE(p.ok) << p.problem;
        double sum = 0;
        const auto& samples = p.passes.front().samples;
        for (size_t k = 1; k < samples.size(); ++k)
            sum += (samples[k].p - samples[k - 1].p).norm();
        EXPECT_NEAR(p.length_mm, sum, 1e-3 * sum);
        // The web (about 258 mm of the square outline) is 1 / cos 30 deg longer.
        EXPECT_GT(p.length_mm, square.length_mm + 30);
        // The time is the length at the speed, plus the ramp and the turns (as the square cut).
        EXPECT_NEAR(p.cut_time_s - square.cut_time_s, (p.length_mm - square.length_mm) / 5,
                    2 * p.dt);
        std::printf("IPE 300 mitre 0/%g deg: %.1f mm, %.1f s (square: %.1f mm, %.1f s)\n", mitre,
                    p.length_mm, p.cut_time_s, square.length_mm, square.cut_time_s);
    }
}

// `cutcell-cli validate` says the real length and time: the shipped square job as before, its
// end mitred 30 deg about z (the flanges' cut lines 1 / cos 30 deg longer) and about y (the
// web's).
TEST(SectionEndCutSpeed, ValidateGivesTheMitredLengthAndTime) {
    std::ifstream in(std::filesystem::path(CUTCELL_SOURCE_DIR) / "resources" / "jobs" /
                     "section_steel_job.json");
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string shipped = ss.str();
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "cutcell_section_speed_validate";
    std::filesystem::create_directories(dir);
    const struct {
        const char *key, *expected;
    } cases[] = {
        {nullptr, "mitre 0.0/0.0 deg, square (path arm), 1010.0 mm at 5.00 mm/s (214.8 s)"},
        {"mitre_vertical_deg", "mitre 30.0/0.0 deg, square (path arm), 1075.6 mm"},
        {"mitre_horizontal_deg", "mitre 0.0/30.0 deg, square (path arm), 1101.0 mm"}};
    for (const auto& c : cases) {
        std::string text = shipped;
        if (c.key) {
            const std::string from = std::string("\"") + c.key + "\": 0";
            const size_t at = text.find(from);
            ASSERT_NE(at, std::string::npos) << from;
            text.replace(at, from.size(), std::string("\"") + c.key + "\": 30");
        }
        std::filesystem::path file = dir / (c.key ? c.key : "square");
        file += ".json";
        std::ofstream(file) << text;
        std::string cmd = CUTCELL_CLI;
        cmd += " validate " + file.string() + " 2>&1";
        FILE* p = popen(cmd.c_str(), "r");
        ASSERT_TRUE(p);
        std::string out;
        char buf[4096];
        while (fgets(buf, sizeof buf, p))
            out += buf;
        EXPECT_EQ(pclose(p), 0) << out;
        EXPECT_NE(out.find(c.expected), std::string::npos) << out;
    }
}
