// Kerf compensation of the section-steel end cut (issue 24): the torch centre k/2 across the cut
// surface (the cut plane, or the bevel surface) toward the scrap side, on the section's faces.
// The theoretical edge is the uncompensated path (EndCut); the checks recompute what they need
// (the cut plane from the mitres, the plane through an edge point spanned by the edge and the
// torch, the outline, the slot swept by the torch jets) without the offset code, except the
// round trip, which is the inverse's own test.
#include "core/common/c_format.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/machines/section_steel/section_kerf.h"
#include "core/machines/section_steel/section_steel_module.h"
#include "core/machines/section_steel/section_steel_planner.h"
#include "core/process/process_spec.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace cutcell;
using namespace cutcell::section_steel;

namespace {

const char* kConsumable = "Powermax65/85 65A shielded";

// A random end cut of any catalogue section, mitres and grooves inside the validated ranges; a
// second setup only where it has something to cut (a K groove on the flanges).
SectionSteelSpec randomSpec(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    const auto& catalogue = sectionCatalogue();
    SectionSteelSpec s = defaultSectionSteelSpec();
    s.section = catalogue[static_cast<size_t>(u(rng) * static_cast<double>(catalogue.size())) %
                          catalogue.size()];
    s.cut.mitre_vertical_deg = u(rng) < 0.3 ? 0 : 90 * u(rng) - 45;
    s.cut.mitre_horizontal_deg = u(rng) < 0.3 ? 0 : 90 * u(rng) - 45;
    auto groove = [&](double thickness) {
        GrooveSpec g;
        g.type = static_cast<GrooveType>(static_cast<int>(4 * u(rng)) % 4);
        g.angle_deg = 5 + 55 * u(rng);
        g.root_face_mm =
            g.type == GrooveType::V || g.type == GrooveType::None ? 0 : 0.4 * thickness * u(rng);
        return g;
    };
    s.cut.flanges = groove(s.section.tf_mm);
    s.cut.web = groove(s.section.tw_mm);
    s.cut.setup = s.cut.flanges.type == GrooveType::K && u(rng) < 0.3 ? 2 : 1;
    return s;
}

std::vector<CutPass> edgePasses(const SectionSteelSpec& s) {
    return EndCut(s).passes(s.knot_spacing_mm / s.speed_mm_s); // as planEndCut samples them
}

// The cut plane from the mitres (section_steel_spec.h's layout): x = y tanV + (z - h/2) tanH,
// in the turned section's coordinates with both mitres negated (setup 2); the unit normal toward
// the bar end (+x).
Eigen::Hyperplane<double, 3> cutPlane(const SectionSteelSpec& s) {
    const double sign = s.cut.setup == 2 ? -1 : 1;
    const double a = sign * std::tan(deg2rad(s.cut.mitre_vertical_deg));
    const double b = sign * std::tan(deg2rad(s.cut.mitre_horizontal_deg));
    const Vec3 n = Vec3(1, -a, -b).normalized();
    return Eigen::Hyperplane<double, 3>(n, Vec3(0, 0, s.section.h_mm / 2));
}

// Job with the section-steel module's default section and a process section (plasma, 65 A).
Job plasmaSteelJob(double kerfOverride_mm) {
    Job job = findMachine(kSectionSteelId)->defaultJob();
    job.process.used = true;
    job.process.process = CutProcess::Plasma;
    job.process.material = "mild_steel";
    job.process.consumable = kConsumable;
    if (kerfOverride_mm > 0) job.process.override.set(CutFigure::KerfMm, kerfOverride_mm);
    return job;
}

SectionSteelSpec& specOf(Job& job) {
    return *job.machine_spec.as<SectionSteelSpec>();
}

std::string textOf(const Job& job) {
    return json::write(jobToJson(job));
}

// The smallest x of the slot of width k (points within k/2 of the jet: the torch axis from
// 60 mm above the tip down to `depth` below it) on the line (x, y0, z0): the kept part's end
// there. +inf when the jet misses the line.
double slotStart(const Vec3& q, const Vec3& dIn, double depth, double k, double y0, double z0) {
    const Vec3 d = dIn.normalized();
    // |w(x) - (w(x) . d) d| = k/2 with w = (x, y0, z0) - q: quadratic in x.
    const Vec3 w0 = Vec3(0, y0, z0) - q, e = Vec3::UnitX();
    const Vec3 a = e - e.dot(d) * d, b = w0 - w0.dot(d) * d;
    const double A = a.squaredNorm(), B = 2 * a.dot(b), C = b.squaredNorm() - k * k / 4;
    const double disc = B * B - 4 * A * C;
    if (A < 1e-15 || disc < 0) return std::numeric_limits<double>::infinity();
    const double x = (-B - std::sqrt(disc)) / (2 * A);
    const double along = (Vec3(x, y0, z0) - q).dot(d); // the nearest jet point
    return along >= -60 && along <= depth ? x : std::numeric_limits<double>::infinity();
}

} // namespace

// (a) Over random sections, mitres, grooves and setups: the edge recovered from the torch path
// (moved back by k/2 across the cut surface) is the theoretical edge; the torch centre is on the
// section's surface, its whole axis k/2 off the cut surface (the independent cut plane on the
// square pass, the plane of edge and torch on a bevel), on the scrap side.
TEST(SectionSteelKerf, EdgeRecoveredAndHalfKerfAcrossOnRandomCuts) {
    std::mt19937 rng(24);
    std::uniform_real_distribution<double> u(0, 1);
    double worstBack = 0, worstAcrossPlane = 0, worstAcrossSurface = 0, worstOnOutline = 0;
    double minScrap = 1e9, maxStretch = 0;
    int cases = 0, refusedStrip = 0, refusedOther = 0;
    size_t points = 0;
    for (int c = 0; c < 400; ++c) {
        const SectionSteelSpec s = randomSpec(rng);
        const double k = 0.05 + 3.95 * u(rng);
        const EndCut cut(s);
        const std::vector<CutPass> edge = edgePasses(s);
        std::vector<CutPass> torch = edge;
        const Outcome o = compensateSteelKerf(cut, torch, k);
        if (!o.ok()) {
            // Refused: only for a bevel too thin for the kerf (or a degenerate bevel surface),
            // with the figures; the passes are left as they were.
            const bool strip = o.message.find("too wide for the") != std::string::npos;
            (strip ? refusedStrip : refusedOther)++;
            EXPECT_NE(o.message.find(strip ? "the kerf may be at most" : "at most"),
                      std::string::npos)
                << o.message;
            for (size_t p = 0; p < edge.size(); ++p)
                for (size_t i = 0; i < edge[p].samples.size(); ++i)
                    ASSERT_EQ(torch[p].samples[i].p, edge[p].samples[i].p);
            continue;
        }
        ++cases;
        std::vector<CutPass> back = torch;
        ASSERT_TRUE(steelEdgeFromTorch(cut, back, k).ok());
        const SectionOutline outline(s.section, s.cut.setup == 2);
        const auto plane = cutPlane(s);
        for (size_t p = 0; p < edge.size(); ++p) {
            const bool square = !edge[p].groove_arm;
            for (size_t i = 0; i < edge[p].samples.size(); ++i) {
                const TorchTarget& e = edge[p].samples[i];
                const TorchTarget& t = torch[p].samples[i];
                ++points;
                worstBack = std::max(worstBack, (back[p].samples[i].p - e.p).norm());
                ASSERT_EQ(t.edge_p, e.p);
                ASSERT_EQ(t.t, e.t); // the torch direction is kept
                const Vec3& q = t.p;
                // On the section's surface: moved along the bar only, on the outline (square
                // pass) or on the bevelled face's plane (a groove's tip lies on the face).
                ASSERT_EQ(q.y(), e.p.y());
                ASSERT_EQ(q.z(), e.p.z());
                const OutlineSegment& face = outline.segments()[e.segment];
                const Vec2 yz(q.y(), q.z());
                worstOnOutline =
                    std::max(worstOnOutline, square ? outline.distanceToOutline(yz)
                                                    : std::fabs((yz - face.p0).dot(face.n0)));
                // The cut surface through the edge point: the cut plane (square pass) or the
                // plane spanned by the edge and the torch (a bevel).
                const auto surface =
                    Eigen::Hyperplane<double, 3>::Through(e.p, e.p + e.edge, e.p + e.t);
                for (double depth : {0.0, 10.0, 40.0}) {
                    const Vec3 x = q + depth * t.t;
                    worstAcrossSurface =
                        std::max(worstAcrossSurface, std::fabs(surface.absDistance(x) - k / 2));
                    if (square)
                        worstAcrossPlane =
                            std::max(worstAcrossPlane, std::fabs(plane.signedDistance(x) - k / 2));
                }
                // Scrap side: past the cut surface toward the bar end.
                Vec3 n = surface.normal();
                if (n.dot(plane.normal()) < 0) n = -n;
                minScrap = std::min(minScrap, (q - e.p).dot(n) / k);
                maxStretch = std::max(maxStretch, (q - e.p).norm() / (k / 2));
            }
        }
    }
    std::printf("%d random cuts compensated (%zu points), %d refused (bevel too thin for the "
                "kerf), %d refused otherwise: edge recovered within %.3g mm; torch axis off the "
                "cut plane by k/2 within %.3g mm (square passes), off the cut surface within "
                "%.3g mm; torch off the outline %.3g mm; (q - p) . n >= %.9f k; |q - p| <= %.4g "
                "x k/2\n",
                cases, points, refusedStrip, refusedOther, worstBack, worstAcrossPlane,
                worstAcrossSurface, worstOnOutline, minScrap, maxStretch);
    EXPECT_GE(cases, 280);
    // Measured: 2.8e-14, 1.1e-13, 2.3e-12, 1.1e-13 mm (issue 24 asks 1e-6 mm).
    EXPECT_LT(worstBack, 1e-12);
    EXPECT_LT(worstAcrossPlane, 1e-12);
    EXPECT_LT(worstAcrossSurface, 1e-10);
    EXPECT_LT(worstOnOutline, 1e-11);
    EXPECT_NEAR(minScrap, 0.5, 1e-12); // k/2 toward the scrap side, never the other way
    EXPECT_LT(maxStretch, 1 / std::cos(deg2rad(80)) + 1e-9);
}

// (b) k = 0 leaves the path and the plan unchanged bit for bit, and so does a process section
// whose chart gives no kerf.
TEST(SectionSteelKerf, ZeroKerfChangesNothing) {
    std::mt19937 rng(5);
    for (int c = 0; c < 40; ++c) {
        const SectionSteelSpec s = randomSpec(rng);
        const std::vector<CutPass> edge = edgePasses(s);
        std::vector<CutPass> same = edge;
        ASSERT_TRUE(compensateSteelKerf(EndCut(s), same, 0.0).ok());
        for (size_t p = 0; p < edge.size(); ++p)
            for (size_t i = 0; i < edge[p].samples.size(); ++i)
                ASSERT_EQ(std::memcmp(same[p].samples[i].p.data(), edge[p].samples[i].p.data(),
                                      sizeof(double) * 3),
                          0);
    }
    SectionSteelSpec s = defaultSectionSteelSpec();
    s.cut.flanges = {GrooveType::V, 30, 0};
    s.cut.mitre_vertical_deg = 15;
    const SteelPlan a = planEndCut(s), b = planEndCut(s, 0.0);
    ASSERT_TRUE(a.ok) << a.problem;
    ASSERT_EQ(a.knots.size(), b.knots.size());
    for (size_t k = 0; k < a.knots.size(); ++k)
        ASSERT_EQ(std::memcmp(a.knots[k].data(), b.knots[k].data(), sizeof(double) * kSteelAxes),
                  0);
    EXPECT_EQ(b.kerf_mm, 0.0);
    EXPECT_EQ(b.frame_shift_mm, 0.0);
    // Through the module: the chart gives no kerf, so the export is the job's without process.
    const MachineModule& m = *findMachine(kSectionSteelId);
    Job plain = m.defaultJob();
    specOf(plain).cut.flanges = {GrooveType::V, 30, 0};
    Job charted = plasmaSteelJob(0);
    specOf(charted).cut.flanges = {GrooveType::V, 30, 0};
    const MachinePlan pa = m.plan(plain), pb = m.plan(charted);
    ASSERT_TRUE(pa.ok() && pb.ok()) << pa.outcome.message << pb.outcome.message;
    EXPECT_EQ(m.exportFile("path_csv", plain, pa), m.exportFile("path_csv", charted, pb));
}

// (c) The kept piece: without compensation the torch on the edge burns k/2 (across the cut
// surface) off it; with compensation its end is the theoretical cut. IPE 300, square end, V 30
// deg on the flanges, k = 1.6 mm. Square pass: along the bar at each torch point of a flat face
// (the jets are parallel there: each one is the nearest to its own point). Top flange's bevel at
// full tilt: along the bar on the upper face, where the bevel strip begins; the piece is
// (k/2) / cos 30 deg shorter there without compensation.
TEST(SectionSteelKerf, UncompensatedPieceIsHalfAKerfShort) {
    SectionSteelSpec s = defaultSectionSteelSpec();
    s.cut.flanges = {GrooveType::V, 30, 0};
    const double k = 1.6, h = s.section.h_mm, tf = s.section.tf_mm;
    const EndCut cut(s);
    const std::vector<CutPass> edge = edgePasses(s);
    std::vector<CutPass> torch = edge;
    ASSERT_TRUE(compensateSteelKerf(cut, torch, k).ok());
    double worstSquare = 0, worstSquareRaw = 0, worstBevel = 0, worstBevelRaw = 0;
    int squarePoints = 0, bevelPoints = 0;
    for (size_t p = 0; p < edge.size(); ++p) {
        const std::vector<TorchTarget>& E = edge[p].samples;
        const std::vector<TorchTarget>& T = torch[p].samples;
        for (size_t i = 0; i < E.size(); i += 3) {
            const TorchTarget& e = E[i];
            const OutlineSegment& seg = cut.outline().segments()[e.segment];
            if (e.turning || seg.arc) continue;
            const double y0 = e.p.y(), z0 = e.p.z();
            if (!edge[p].groove_arm) {
                // The plate under this face point is at most tf or tw thick: jets 30 mm deep.
                double end = std::numeric_limits<double>::infinity(), raw = end;
                for (size_t j = (i < 3 ? 0 : i - 3); j < std::min(E.size(), i + 4); ++j) {
                    end = std::min(end, slotStart(T[j].p, T[j].t, 30, k, y0, z0));
                    raw = std::min(raw, slotStart(E[j].p, E[j].t, 30, k, y0, z0));
                }
                worstSquare = std::max(worstSquare, std::fabs(end - 0.0));
                worstSquareRaw = std::max(worstSquareRaw, std::fabs(raw - (-k / 2)));
                ++squarePoints;
            } else if (std::fabs(e.tilt_rad - deg2rad(30)) < 1e-12 && e.lean_rad == 0 &&
                       std::fabs(z0 - h) < 1e-9) {
                // The bevel strip on the top flange's upper face: it begins at the edge point.
                const double end = slotStart(T[i].p, T[i].t, tf / std::cos(deg2rad(30)), k, y0, z0);
                const double raw = slotStart(E[i].p, E[i].t, tf / std::cos(deg2rad(30)), k, y0, z0);
                worstBevel = std::max(worstBevel, std::fabs(end - e.p.x()));
                worstBevelRaw = std::max(
                    worstBevelRaw, std::fabs(raw - (e.p.x() - k / 2 / std::cos(deg2rad(30)))));
                ++bevelPoints;
            }
        }
    }
    std::printf("square end over %d points: compensated end at the cut within %.3g mm, "
                "uncompensated k/2 = %.3g mm short within %.3g mm; top flange bevel over %d "
                "points: compensated within %.3g mm, uncompensated (k/2)/cos 30 = %.6g mm short "
                "within %.3g mm\n",
                squarePoints, worstSquare, k / 2, worstSquareRaw, bevelPoints, worstBevel,
                k / 2 / std::cos(deg2rad(30)), worstBevelRaw);
    EXPECT_GE(squarePoints, 100);
    EXPECT_GE(bevelPoints, 10);
    // Measured: 0, 0, 2.7e-15, 8.9e-16 mm.
    EXPECT_LT(worstSquare, 1e-13);
    EXPECT_LT(worstSquareRaw, 1e-13);
    EXPECT_LT(worstBevel, 1e-13);
    EXPECT_LT(worstBevelRaw, 1e-13);
}

// (d) The plan and its program carry the torch path: the arms' joints put the torch on the
// compensated targets (forward kinematics of the program's tip model at every knot), the square
// pass's arm plane moved along the bar, the export with the edge beside the torch.
TEST(SectionSteelKerf, PlanProgramAndExportCarryTheTorchPath) {
    const MachineModule& m = *findMachine(kSectionSteelId);
    for (const double mitre : {0.0, 20.0}) {
        Job job = plasmaSteelJob(1.6);
        specOf(job).cut.flanges = {GrooveType::V, 30, 0};
        specOf(job).cut.mitre_vertical_deg = mitre;
        specOf(job).cut.mitre_horizontal_deg = mitre / 2;
        ASSERT_TRUE(m.validate(job).empty()) << m.validate(job).front().message;
        const MachinePlan plan = m.plan(job);
        ASSERT_TRUE(plan.ok()) << plan.outcome.message;
        EXPECT_NE(plan.summary.find("kerf 1.60 mm compensated"), std::string::npos) << plan.summary;
        const auto* steel = static_cast<const SteelPlan*>(plan.data.get());
        EXPECT_EQ(steel->kerf_mm, 1.6);
        const Vec3 mNormal = EndCut(specOf(job)).planeNormal();
        EXPECT_NEAR(steel->frame_shift_mm, 0.8 / mNormal.x(), 1e-12);
        double worstTip = 0, worstMove = 0;
        for (size_t k = 0; k < steel->knots.size(); ++k) {
            const KnotInfo& info = steel->info[k];
            if (info.pass < 0) continue;
            const TorchTarget& t =
                steel->passes[static_cast<size_t>(info.pass)].samples[info.sample];
            const Vec3 tip = plan.program->tip_model->tip(plan.program->spline.knot(k));
            worstTip = std::max(worstTip, (tip - t.p).norm());
            worstMove = std::max(worstMove, (t.p - t.edge_p).norm());
        }
        std::printf("mitre %.0f/%.0f deg: program tip on the torch path within %.3g mm (plan FK "
                    "%.3g mm), the torch up to %.6g mm off the edge, frame shift %.6g mm\n",
                    mitre, mitre / 2, worstTip, steel->max_torch_error_mm, worstMove,
                    steel->frame_shift_mm);
        // Measured: 4.0e-12 mm square, 1.8e-11 mm mitred.
        EXPECT_LT(worstTip, 1e-9);
        EXPECT_LT(steel->max_torch_error_mm, 1e-9);
        EXPECT_GT(worstMove, 0.8);
        // The export: the torch centre in x, y, z and the edge in the last three columns.
        const std::string csv = m.exportFile("path_csv", job, plan);
        EXPECT_NE(csv.find(",edge_x_mm,edge_y_mm,edge_z_mm\n"), std::string::npos);
        const size_t row = csv.find('\n') + 1;
        const std::string first = csv.substr(row, csv.find('\n', row) - row);
        const TorchTarget& t0 = steel->passes[0].samples[0];
        EXPECT_NE(first.find(formatC(",%.4f,%.4f,%.4f,", t0.p.x(), t0.p.y(), t0.p.z())),
                  std::string::npos)
            << first;
        EXPECT_NE(
            first.find(formatC(",%.4f,%.4f,%.4f", t0.edge_p.x(), t0.edge_p.y(), t0.edge_p.z())),
            std::string::npos)
            << first;
    }
}

// (e) A kerf too wide for a bevel is refused with the kerf, the bevel's key, its angle and the
// largest kerf: a V 5 deg bevel through the IPE 300's 10.7 mm flange takes a strip D tan 5 deg
// off the face, the torch centre (k/2)/cos 5 deg into it: at most 2 D sin 5 deg = 1.865 mm.
TEST(SectionSteelKerf, KerfTooWideForTheBevelIsRefused) {
    const MachineModule& m = *findMachine(kSectionSteelId);
    Job job = plasmaSteelJob(3.0);
    specOf(job).cut.flanges = {GrooveType::V, 5, 0};
    ASSERT_TRUE(m.validate(job).empty());
    const MachinePlan plan = m.plan(job);
    ASSERT_FALSE(plan.ok());
    EXPECT_EQ(plan.outcome.key, "process.override.kerf_mm");
    const std::string& msg = plan.outcome.message;
    std::printf("refusal: %s\n", msg.c_str());
    const double limit = 2 * specOf(job).section.tf_mm * std::sin(deg2rad(5));
    for (const std::string& part :
         {std::string("kerf compensation: the kerf 3 mm is too wide for the V bevel of "
                      "end_cut.flanges (end_cut.flanges.angle_deg = 5 deg)"),
          formatC("the kerf may be at most %.6g mm", limit)})
        EXPECT_NE(msg.find(part), std::string::npos) << part;
    // The plan is kept on the edge for the view, refused.
    const auto* steel = static_cast<const SteelPlan*>(plan.data.get());
    ASSERT_NE(steel, nullptr);
    EXPECT_EQ(steel->kerf_mm, 0.0);
    EXPECT_FALSE(steel->ok);
    // Just below the limit the same cut is compensated and planned.
    Job fits = plasmaSteelJob(std::floor(limit * 1000) / 1000);
    specOf(fits).cut.flanges = {GrooveType::V, 5, 0};
    const MachinePlan ok = m.plan(fits);
    EXPECT_TRUE(ok.ok()) << ok.outcome.message;
    // A negative or non-finite kerf never reaches the plan from a job (the override's range) but
    // is refused by the maths too.
    std::vector<CutPass> passes = edgePasses(specOf(job));
    const Outcome neg = compensateSteelKerf(EndCut(specOf(job)), passes, -1);
    EXPECT_NE(neg.message.find("the kerf -1 mm is negative"), std::string::npos) << neg.message;
}

// (f) A section-steel job with a process section: read -> write -> read keeps it (its place
// after the section), the chart row is picked by the thickest plate, the override is the kerf,
// a speed override is refused (this machine cuts at motion.speed_mm_s), and a bad key in the
// section is refused by the shared reader.
TEST(SectionSteelKerf, JobProcessSectionRoundTrip) {
    Job job = plasmaSteelJob(1.7);
    job.process.thickness_mm = 12;
    const std::string text = textOf(job);
    const Job back = parseJob(text);
    EXPECT_TRUE(back.process.used);
    EXPECT_EQ(back.process, job.process);
    EXPECT_EQ(textOf(back), text);
    EXPECT_EQ(textOf(parseJob(textOf(back))), text);
    EXPECT_TRUE(validateJob(back).empty());
    EXPECT_DOUBLE_EQ(steelKerfMm(back), 1.7);
    const size_t section = text.find("\"section\""), process = text.find("\"process\""),
                 endCut = text.find("\"end_cut\"");
    EXPECT_TRUE(section < process && process < endCut) << text;
    // Without a thickness the thickest plate picks the row (IPE 300: tf 10.7 > tw 7.1 mm).
    Job plate = plasmaSteelJob(0);
    EXPECT_DOUBLE_EQ(steelPartThicknessMm(specOf(plate)), 10.7);
    const ProcessSettings settings = resolveProcess(plate.process, 10.7);
    ASSERT_TRUE(settings.ok()) << settings.outcome.message;
    EXPECT_EQ(steelKerfMm(plate), 0.0); // the shipped chart gives no kerf
    // No process section: none written, none read.
    const Job plain = parseJob(textOf(findMachine(kSectionSteelId)->defaultJob()));
    EXPECT_FALSE(plain.process.used);
    EXPECT_EQ(textOf(plain).find("\"process\""), std::string::npos);
    // A speed override would be ignored by this machine: refused with its key.
    Job speed = plasmaSteelJob(1.7);
    speed.process.override.set(CutFigure::CutSpeedMmMin, 900);
    EXPECT_THROW(parseJob(textOf(speed)), JobError);
    const auto issues = validateJob(speed);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].key, "process.override.cut_speed_mm_min");
    EXPECT_NE(issues[0].message.find("motion.speed_mm_s = 5 mm/s"), std::string::npos)
        << issues[0].message;
    // A plate outside the chart (45 A: 0.5 .. 6 mm) is an issue of the process section.
    Job thin = plasmaSteelJob(1.7);
    thin.process.consumable = "Powermax65/85 45A shielded";
    const auto outside = validateJob(thin);
    ASSERT_FALSE(outside.empty());
    EXPECT_EQ(outside[0].key, "process.thickness_mm");
    EXPECT_NE(outside[0].message.find("10.7 mm"), std::string::npos) << outside[0].message;
    // The shared reader's refusals: an unknown key, a kerf override out of its range.
    auto refused = [&](const std::string& from, const std::string& to, const std::string& needle) {
        std::string t = text;
        const size_t at = t.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        t.replace(at, from.size(), to);
        try {
            const Job j = parseJob(t);
            const auto found = validateJob(j);
            ASSERT_FALSE(found.empty()) << "accepted: " << to;
            EXPECT_NE(found[0].message.find(needle), std::string::npos) << found[0].message;
        } catch (const JobError& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    };
    refused("\"kerf_mm\": 1.7", "\"kerf_mm\": 1.7, \"kerf_in\": 1", "kerf_in");
    refused("\"kerf_mm\": 1.7", "\"kerf_mm\": 40", "process.override.kerf_mm = 40 mm");
}
