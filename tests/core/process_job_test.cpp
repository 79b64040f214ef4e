// The job's process section (issue 24): the cut chart's row picked by the part's wall
// (interpolated, refused outside the chart with its range), overrides saved and marked, the cut
// speed taken from the chart, and the robot's plan compensating the kerf: the torch centre runs
// k/2 off the edge so the hole is the edge's size, where the torch on the edge burns it k wider.
#include "core/geometry/cut_path.h"
#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/machine/pipe_joint_section.h"
#include "core/machines/pipe_robot/cut_planner.h"
#include "core/process/kerf_offset.h"
#include "core/process/process_spec.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace cutcell;

namespace {

const char* kConsumable = "Powermax65/85 65A shielded";

// The default robot job (the hole in a DN100 pipe of wall 6.02 mm) cut by plasma.
Job plasmaJob() {
    Job job = defaultJob();
    job.process.used = true;
    job.process.process = CutProcess::Plasma;
    job.process.material = "mild_steel";
    job.process.consumable = kConsumable;
    syncProcessSpeed(job);
    return job;
}

std::string textOf(const Job& job) {
    return json::write(jobToJson(job));
}

// The chart's figure at thickness t by linear interpolation, done here from the chart's rows.
double interpolate(const CutChart& chart, CutFigure f, double t) {
    for (size_t i = 0; i + 1 < chart.rows.size(); ++i) {
        const double a = chart.rows[i].thicknessMm(), b = chart.rows[i + 1].thicknessMm();
        if (t >= a && t <= b)
            return *chart.rows[i].get(f) +
                   (t - a) / (b - a) * (*chart.rows[i + 1].get(f) - *chart.rows[i].get(f));
    }
    ADD_FAILURE() << t << " mm is outside the chart";
    return 0;
}

bool hasIssue(const std::vector<JobIssue>& issues, const std::string& key,
              const std::string& text) {
    return std::any_of(issues.begin(), issues.end(), [&](const JobIssue& i) {
        return i.key == key && i.message.find(text) != std::string::npos;
    });
}

} // namespace

TEST(ProcessJob, TheWallPicksTheChartRowAndTheSpeed) {
    const Job job = parseJob(textOf(plasmaJob()));
    ASSERT_TRUE(job.process.used);
    const CutChart* chart = shippedCutCharts().find(CutProcess::Plasma, "mild_steel", kConsumable);
    ASSERT_NE(chart, nullptr);
    const double wall = job.main_pipe.wall_mm; // the hole is cut in the main pipe
    const double expected = interpolate(*chart, CutFigure::CutSpeedMmMin, wall);
    EXPECT_NEAR(job.cut.speed_mm_s * 60, expected, 1e-9);
    const ProcessSettings s = resolveProcess(job.process, wall);
    ASSERT_TRUE(s.ok()) << s.outcome.message;
    EXPECT_TRUE(s.thickness_from_part);
    EXPECT_FALSE(s.overridden(CutFigure::CutSpeedMmMin));
    EXPECT_NEAR(*s.effective.get(CutFigure::PierceDelayS),
                interpolate(*chart, CutFigure::PierceDelayS, wall), 1e-12);
    EXPECT_TRUE(validateJob(job).empty());
    // The speed is written by the chart only: the file has no cut.speed_mm_s.
    EXPECT_EQ(textOf(job).find("\"speed_mm_s\""), std::string::npos);
}

TEST(ProcessJob, AnOverrideIsSavedReadBackAndMarked) {
    Job job = plasmaJob();
    job.process.override.set(CutFigure::KerfMm, 1.6);
    job.process.override.set(CutFigure::CutSpeedMmMin, 1500);
    syncProcessSpeed(job);
    const std::string text = textOf(job);
    EXPECT_NE(text.find("\"override\""), std::string::npos);
    const Job back = parseJob(text);
    EXPECT_EQ(back.process, job.process);
    EXPECT_EQ(textOf(back), text);
    EXPECT_NEAR(back.cut.speed_mm_s, 1500.0 / 60, 1e-12);
    const ProcessSettings s = resolveProcess(back.process, back.main_pipe.wall_mm);
    EXPECT_TRUE(s.overridden(CutFigure::KerfMm));
    EXPECT_TRUE(s.overridden(CutFigure::CutSpeedMmMin));
    EXPECT_FALSE(s.overridden(CutFigure::PierceDelayS));
    EXPECT_FALSE(s.chart_row.get(CutFigure::KerfMm).has_value()); // the chart has none
    EXPECT_DOUBLE_EQ(s.kerfMm(), 1.6);
}

TEST(ProcessJob, AThicknessOutsideTheChartIsRefusedWithItsRange) {
    Job job = plasmaJob();
    job.process.thickness_mm = 30;
    syncProcessSpeed(job);
    const auto issues = validateJob(job);
    EXPECT_TRUE(hasIssue(issues, "process.thickness_mm", "30 mm is outside the chart"));
    EXPECT_TRUE(hasIssue(issues, "process.thickness_mm", ": 3 .. 16 mm"));
    // Without a thickness the part's wall picks the row, and the message says so.
    Job thin = plasmaJob();
    thin.main_pipe.wall_mm = 2;
    syncProcessSpeed(thin);
    EXPECT_TRUE(hasIssue(validateJob(thin), "process.thickness_mm", "the part's wall 2 mm"));
}

TEST(ProcessJob, BadProcessSectionsAreRefused) {
    const std::string good = textOf(plasmaJob());
    auto replaced = [&](const std::string& from, const std::string& to) {
        std::string t = good;
        const size_t at = t.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return t.replace(at, from.size(), to);
    };
    // Two speeds for one cut.
    try {
        parseJob(replaced("\"target\": \"main\"", "\"target\": \"main\", \"speed_mm_s\": 4"));
        ADD_FAILURE() << "a second speed was accepted";
    } catch (const JobError& e) {
        EXPECT_NE(std::string(e.what()).find("cut.speed_mm_s"), std::string::npos) << e.what();
    }
    // An unknown key, and a figure that does not apply to the process.
    EXPECT_THROW(parseJob(replaced("\"material\"", "\"kerf\": 1, \"material\"")), JobError);
    EXPECT_THROW(
        parseJob(replaced("\"material\"", "\"override\": {\"preheat_s\": 5}, \"material\"")),
        JobError);
    // An override outside its figure's range.
    Job wide = plasmaJob();
    wide.process.override.set(CutFigure::KerfMm, 50);
    EXPECT_TRUE(hasIssue(validateJob(wide), "process.override.kerf_mm", "50 mm is outside"));
    // An unknown consumable names the known ones.
    Job unknown = plasmaJob();
    unknown.process.consumable = "200A";
    syncProcessSpeed(unknown);
    EXPECT_TRUE(hasIssue(validateJob(unknown), "process.consumable", kConsumable));
}

namespace {

// The robot's plan of the hole with knots close together (the hole's extent from its points).
CutPlan holePlan(double kerf_mm) {
    Job job = plasmaJob();
    if (kerf_mm > 0) job.process.override.set(CutFigure::KerfMm, kerf_mm);
    job.cut.knot_spacing_mm = 0.1;
    return planCut(job);
}

double extentAlongMainAxis(const std::vector<Vec3>& pts) {
    double lo = 1e300, hi = -1e300;
    for (const Vec3& p : pts) {
        lo = std::min(lo, p.z());
        hi = std::max(hi, p.z());
    }
    return hi - lo;
}

} // namespace

TEST(ProcessJob, TheRobotCompensatesTheKerfAndTheHoleKeepsItsSize) {
    const double k = 1.6;
    Job job = plasmaJob();
    job.process.override.set(CutFigure::KerfMm, k);
    const CutGeometry geo(job);
    const KerfPathSpec spec = kerfPathSpecFor(job, geo);
    const CutPlan with = holePlan(k), without = holePlan(0);
    ASSERT_TRUE(with.reachable) << with.problem;
    ASSERT_TRUE(without.reachable) << without.problem;
    EXPECT_EQ(with.kerf_mm, k);
    // The slot's near face (the torch point moved back k/2) is the theoretical edge: the edge
    // recovered from every torch point is the edge at the same arc length, within 1e-6 mm.
    std::vector<CutPoint> torch;
    for (const PlannedPoint& p : with.knots)
        torch.push_back(p.cut);
    const KerfPath back = edgeFromTorchPath(spec, torch, k);
    ASSERT_TRUE(back.outcome.ok()) << back.outcome.message;
    double worst = 0;
    for (size_t i = 0; i < back.points.size(); ++i)
        worst =
            std::max(worst, (back.points[i].p_main - geo.atArcLength(torch[i].s_mm).p_main).norm());
    EXPECT_LT(worst, 1e-6);
    // Hole width along the main pipe, with and without compensation: the burned hole ends at
    // the slot's kept-side face, k/2 from the torch centre away from the scrap side.
    auto burned = [&](const CutPlan& plan) {
        std::vector<CutPoint> path;
        for (const PlannedPoint& p : plan.knots)
            path.push_back(p.cut);
        const KerfPath face = edgeFromTorchPath(spec, path, k);
        EXPECT_TRUE(face.outcome.ok());
        std::vector<Vec3> pts;
        for (const CutPoint& c : face.points)
            pts.push_back(c.p_main);
        return extentAlongMainAxis(pts);
    };
    std::vector<Vec3> edge;
    for (const CutPoint& c : geo.sampleEqualArcLength(0.05))
        edge.push_back(c.p_main);
    const double theoretical = extentAlongMainAxis(edge);
    const double compensated = burned(with), uncompensated = burned(without);
    std::printf("hole width along the main pipe: edge %.4f mm, cut with compensation %.4f mm, "
                "without %.4f mm (k = %.2f mm)\n",
                theoretical, compensated, uncompensated, k);
    EXPECT_NEAR(compensated, theoretical, 0.005);
    EXPECT_NEAR(uncompensated - theoretical, k, 0.005);
}

// The robot plans leads (robot_lead.h): a lead asked for needs the pierce and the cut height,
// an issue naming the key until the chart or an override gives them - never ignored.
TEST(ProcessJob, ARobotJobWithALeadInNeedsItsHeights) {
    Job job = plasmaJob();
    ASSERT_TRUE(validateJob(job).empty());
    job.process.lead_in.kind = LeadKind::Arc;
    job.process.lead_in.length_mm = 5;
    const bool chartHasIt = resolveProcess(job.process, cutPartWallMm(job))
                                .effective.get(CutFigure::PierceHeightMm)
                                .has_value();
    if (!chartHasIt) {
        EXPECT_TRUE(hasIssue(validateJob(job), "process.override.pierce_height_mm",
                             "needs the pierce height"));
    }
    job.process.override.set(CutFigure::PierceHeightMm, 3.8);
    job.process.override.set(CutFigure::CutHeightMm, 1.5);
    EXPECT_TRUE(validateJob(job).empty());
    // Piercing below the cut height is refused with the key and the least that works.
    job.process.override.set(CutFigure::PierceHeightMm, 1.0);
    EXPECT_TRUE(hasIssue(validateJob(job), "process.override.pierce_height_mm",
                         "pierce height 1 mm is below the cut height 1.5 mm"));
    job.process.lead_in.kind = LeadKind::None;
    job.process.lead_in.length_mm = 0;
    EXPECT_TRUE(validateJob(job).empty());
}

// A lead's length without a lead is refused (never read and dropped); an overlap alone is kept.
TEST(ProcessJob, ALeadsFiguresWithoutALeadAreNotDropped) {
    const std::string good = textOf(plasmaJob());
    const size_t at = good.find("\"material\"");
    ASSERT_NE(at, std::string::npos);
    std::string text = good;
    text.insert(at, R"("lead_in": {"kind": "none", "length_mm": 5}, )");
    try {
        parseJob(text);
        ADD_FAILURE() << "a length without a lead was accepted";
    } catch (const JobError& e) {
        EXPECT_NE(std::string(e.what()).find("lead_in.length_mm is given but"), std::string::npos)
            << e.what();
    }
    text = good;
    text.insert(at, R"("lead_out": {"kind": "none", "overlap_mm": 3}, )");
    // An overlap alone is a lead the robot plans (the cut runs on 3 mm): read, kept, valid.
    const Job job = parseJob(text);
    EXPECT_EQ(job.process.lead_out.overlap_mm, 3);
    EXPECT_TRUE(validateJob(job).empty());
}

// process.torch_height (the robot's THC): the shipped job round-trips through the file; an
// unknown key, a noise or a simulated pipe outside its range are refused naming key, value,
// unit and limit; the machines without a THC refuse the keys with the reason.
TEST(ProcessJob, TorchHeightKeysRoundTripAndAreChecked) {
    const std::string path =
        std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/plasma_thc_job.json";
    const Job job = loadJobFile(path);
    ASSERT_TRUE(job.process.torch_height.used);
    EXPECT_TRUE(job.process.torch_height.thc);
    EXPECT_EQ(job.process.torch_height.ovality_mm, 2);
    EXPECT_EQ(job.process.torch_height.runout_mm, 0.5);
    EXPECT_TRUE(validateJob(job).empty());
    const Job again = parseJob(textOf(job));
    EXPECT_TRUE(again.process == job.process);

    const std::string good = textOf(job);
    auto replaced = [&](const std::string& from, const std::string& to) {
        std::string t = good;
        const size_t at = t.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return t.replace(at, from.size(), to);
    };
    try {
        parseJob(replaced("\"thc\"", "\"volts\": 3, \"thc\""));
        ADD_FAILURE() << "an unknown key was accepted";
    } catch (const JobError& e) {
        EXPECT_NE(std::string(e.what()).find("process.torch_height.volts"), std::string::npos)
            << e.what();
    }
    Job noisy = job;
    noisy.process.torch_height.arc_noise_v = 12;
    EXPECT_TRUE(hasIssue(validateJob(noisy), "process.torch_height.arc_noise_v", "12 V"));
    Job oval = job;
    oval.process.torch_height.ovality_mm = 6; // the DN40 branch: 10 % of 48.3 mm is 4.83 mm
    EXPECT_TRUE(hasIssue(validateJob(oval), "process.torch_height.simulated_pipe.ovality_mm",
                         "ovality_mm = 6 mm is outside 0 .. 4.83 mm"));
    Job eccentric = job;
    eccentric.process.torch_height.runout_mm = 3;
    EXPECT_TRUE(hasIssue(validateJob(eccentric), "process.torch_height.simulated_pipe.runout_mm",
                         "runout_mm = 3 mm is outside 0 .. 2.415 mm"));
}
