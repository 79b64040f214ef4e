// The profile cutter's leads in the engine's program (profile_cutter_program.h) and in path.csv:
// every lead point is a knot the spline passes through, lead-in before cut before lead-out, the
// torch lit at the pierce point for the chart's pierce delay, a job without leads unchanged, and
// the shipped lead-in job run to Completed on the simulated rig.
#include "core/engine/motion_engine.h"
#include "core/job/job_io.h"
#include "core/machine/pipe_joint_section.h"
#include "core/machines/profile_cutter/profile_csv.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"
#include "core/machines/profile_cutter/profile_cutter_program.h"
#include "core/machines/profile_cutter/profile_lead.h"
#include "core/process/process_spec.h"
#include "core/trajectory/speed_profile.h"
#include "devices/machines/sim_rig_registry.h"
#include "profile_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cutcell {
namespace {

Job leadInJob() {
    return loadJobFile(std::string(CUTCELL_SOURCE_DIR) +
                       "/resources/jobs/profile_cutter_lead_in_job.json");
}

// The shipped lead-in job and variations of its leads and target.
std::vector<Job> leadJobs() {
    std::vector<Job> out{leadInJob()};
    Job lines = leadInJob();
    lines.process.lead_in = {LeadKind::Line, 4, 0};
    lines.process.lead_out = {LeadKind::Arc, 3, 0};
    out.push_back(lines);
    Job overlapOnly = leadInJob();
    overlapOnly.process.lead_in = {LeadKind::None, 0, 0};
    overlapOnly.process.lead_out = {LeadKind::None, 0, 3};
    out.push_back(overlapOnly);
    Job branch = leadInJob();
    branch.cut.target = CutTarget::Branch;
    branch.process.lead_in = {LeadKind::Line, 5, 0};
    branch.process.lead_out = {LeadKind::Line, 5, 2};
    out.push_back(branch);
    return out;
}

const ProfileCutterPlanData& planData(const MachinePlan& plan) {
    return *static_cast<const ProfileCutterPlanData*>(plan.data.get());
}

TEST(ProfileLeadProgram, SplinePassesThroughEveryLeadPointInOrder) {
    const ProfileCutterModule module;
    for (const Job& job : leadJobs()) {
        const MachinePlan plan = module.plan(job, {}, {});
        ASSERT_TRUE(plan.ok()) << job.name << ": " << plan.outcome.message;
        const ProfileLeads& leads = planData(plan).leads;
        ASSERT_TRUE(leads.used);
        ProfileProgramLayout layout;
        const auto p = buildProfileCutterProgram(job, leads, {}, &layout);
        ASSERT_EQ(layout.lead_in_knots.size(), leads.lead_in.size());
        ASSERT_EQ(layout.lead_out_knots.size(), leads.lead_out.size());
        // The plan's program is the same one.
        ASSERT_EQ(plan.program->spline.knotCount(), p->spline.knotCount());
        EXPECT_EQ(p->point_count, p->spline.knotCount());
        EXPECT_NEAR(p->cut_time_s, p->spline.duration(), 1e-9);
        const double dt = p->spline.dt();
        double worst = 0;
        auto through = [&](size_t knot, const ProfilePoint& pt) {
            const JointSample s = p->spline.evaluate(dt * static_cast<double>(knot));
            worst = std::max(
                {worst, std::fabs(s.q[0] - deg2rad(pt.a_deg)), std::fabs(s.q[1] - pt.x_mm)});
            EXPECT_NEAR(s.q[0], deg2rad(pt.a_deg), 1e-9) << "knot " << knot;
            EXPECT_NEAR(s.q[1], pt.x_mm, 1e-9) << "knot " << knot;
        };
        for (size_t i = 0; i < leads.lead_in.size(); ++i)
            through(layout.lead_in_knots[i], leads.lead_in[i]);
        for (size_t i = 0; i < leads.lead_out.size(); ++i)
            through(layout.lead_out_knots[i], leads.lead_out[i]);
        // In time: pierce point first, lead-in, cut, lead-out, its end the last knot.
        std::vector<size_t> order = layout.lead_in_knots;
        order.push_back(layout.cut_first_knot);
        order.push_back(layout.cut_last_knot);
        order.insert(order.end(), layout.lead_out_knots.begin(), layout.lead_out_knots.end());
        EXPECT_EQ(order.front(), 0u);
        EXPECT_EQ(order.back(), p->spline.knotCount() - 1);
        for (size_t i = 1; i < order.size(); ++i)
            EXPECT_LT(order[i - 1], order[i]) << i;
        EXPECT_GT(layout.cut_last_knot - layout.cut_first_knot, 16u);
        // The cruise window on the cut only; the leads at most the cutting speed (+ spline).
        EXPECT_GE(p->cruise_from_s, dt * static_cast<double>(layout.cut_first_knot) - 1e-12);
        EXPECT_LE(p->cruise_to_s, dt * static_cast<double>(layout.cut_last_knot) + 1e-12);
        EXPECT_LT(p->cruise_from_s, p->cruise_to_s);
        const double R = planData(plan).cut.work_radius_mm, v = job.cut.speed_mm_s;
        double fastest = 0, cruiseOff = 0;
        for (double t = 0; t <= p->cut_time_s; t += 0.002) {
            const JointSample s = p->spline.evaluate(t);
            const double speed = std::hypot(s.qd[1], R * s.qd[0]);
            fastest = std::max(fastest, speed / v);
            if (t >= p->cruise_from_s && t <= p->cruise_to_s)
                cruiseOff = std::max(cruiseOff, std::fabs(speed - v) / v);
        }
        // A line lead meets the cut square: the spline rounds that corner too fast - a known
        // defect (README), measured 1.061 v on the branch end's line lead; bound near it so a
        // worse corner fails. The cruise is the cut's own speed (measured within 0.0005).
        EXPECT_LT(fastest, 1.07);
        EXPECT_LT(cruiseOff, 0.002);
        EXPECT_LT(p->spline.evaluate(0).qd.norm(), 1e-9);
        EXPECT_LT(p->spline.evaluate(p->cut_time_s).qd.norm(), 1e-9);
        std::printf("[ figures  ] %s / in %s %.1f, out %s %.1f + %.1f: %zu knots, dt %.4f s, "
                    "%.2f s, %.2f mm; lead-in %zu, lead-out %zu points; worst miss %.2e; "
                    "fastest %.4f v, cruise off %.4f\n",
                    toString(job.cut.target), toString(leads.in.kind), leads.in.length_mm,
                    toString(leads.out.kind), leads.out.length_mm, leads.out.overlap_mm,
                    p->spline.knotCount(), dt, p->cut_time_s, p->length_mm, leads.lead_in.size(),
                    leads.lead_out.size(), worst, fastest, cruiseOff);
    }
}

TEST(ProfileLeadProgram, PierceDelayIsTheCharts) {
    const Job job = leadInJob();
    const ProcessSettings s = resolveProcess(job.process, cutPartWallMm(job));
    ASSERT_TRUE(s.ok()) << s.outcome.message;
    const std::optional<double> chart = s.effective.get(CutFigure::PierceDelayS);
    ASSERT_TRUE(chart.has_value()) << "the chart row gives no pierce delay";
    const auto p = buildProfileCutterProgram(job);
    EXPECT_EQ(p->pierce_s, *chart);
    EXPECT_NE(p->pierce_s, profileCutterSpec(job).pierce_s) << "the chart's, not the machine's";
    std::printf("[ figures  ] pierce_s %.3f s (chart), machine's pierce_s %.3f s\n", p->pierce_s,
                profileCutterSpec(job).pierce_s);
}

// The old program (the cut alone), rebuilt here: a job without lead keys gets exactly it.
TEST(ProfileLeadProgram, NoLeadKeysLeaveTheProgramUnchanged) {
    std::vector<Job> jobs{test::exampleProfileJob()};
    Job noLeads = leadInJob();
    noLeads.process.lead_in = {LeadKind::None, 0, 0};
    noLeads.process.lead_out = {LeadKind::None, 0, 0};
    jobs.push_back(noLeads);
    for (const Job& job : jobs) {
        const auto p = buildProfileCutterProgram(job);
        const ProfileCut cut =
            computeProfileCut(job, std::max(4096, 8 * profileCutterSpec(job).steps_per_rev_a));
        const DevelopedPath path(cut);
        const SpeedProfile profile(path.length(), job.cut.speed_mm_s, job.cut.ramp_s);
        const int intervals =
            std::max(16, static_cast<int>(std::ceil(path.length() / job.cut.knot_spacing_mm)));
        const double dt = profile.duration() / intervals;
        EXPECT_EQ(p->cut_time_s, profile.duration());
        EXPECT_EQ(p->spline.dt(), dt);
        EXPECT_EQ(p->point_count, static_cast<size_t>(intervals) + 1);
        EXPECT_EQ(p->length_mm, path.length());
        EXPECT_EQ(p->pierce_s, profileCutterSpec(job).pierce_s);
        ASSERT_EQ(p->spline.knotCount(), static_cast<size_t>(intervals) + 1);
        for (int k = 0; k <= intervals; ++k) {
            double a = 0, x = 0;
            path.at(profile.distance(dt * k), &a, &x);
            ASSERT_EQ(p->spline.knot(static_cast<size_t>(k))[0], deg2rad(a)) << k;
            ASSERT_EQ(p->spline.knot(static_cast<size_t>(k))[1], x) << k;
        }
        const MachinePlan plan = ProfileCutterModule().plan(job, {}, {});
        ASSERT_TRUE(plan.ok()) << plan.outcome.message;
        EXPECT_EQ(plan.program->spline.knotCount(), p->spline.knotCount());
        EXPECT_EQ(plan.program->cut_time_s, p->cut_time_s);
        // path.csv as before: no "part" column.
        const std::string csv = ProfileCutterModule().exportFile("path_csv", job, plan);
        EXPECT_EQ(csv, profilePathCsv(planData(plan).cut, planData(plan).schedule));
        EXPECT_EQ(csv.find("part"), std::string::npos);
    }
}

TEST(ProfileLeadProgram, PathCsvMarksTheLeadRows) {
    const Job job = leadInJob();
    const ProfileCutterModule module;
    const MachinePlan plan = module.plan(job, {}, {});
    ASSERT_TRUE(plan.ok()) << plan.outcome.message;
    const ProfileCutterPlanData& d = planData(plan);
    const std::string csv = module.exportFile("path_csv", job, plan);
    std::vector<std::string> lines;
    for (size_t at = 0, nl; (nl = csv.find('\n', at)) != std::string::npos; at = nl + 1)
        lines.push_back(csv.substr(at, nl - at));
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines[0].substr(lines[0].size() - 5), ",part");
    const size_t nIn = d.leads.lead_in.size(), nOut = d.leads.lead_out.size();
    const size_t nCut = d.cut.points.size() + 1;
    ASSERT_EQ(lines.size(), 1 + nIn + nCut + nOut);
    auto part = [](const std::string& l) { return l.substr(l.rfind(',') + 1); };
    for (size_t i = 1; i < lines.size(); ++i) {
        const char* want = i <= nIn ? "lead_in" : i <= nIn + nCut ? "cut" : "lead_out";
        EXPECT_EQ(part(lines[i]), want) << lines[i];
        EXPECT_EQ(std::stoul(lines[i]), i - 1) << lines[i];
    }
    // The pierce point's row: X/A of the first lead-in point, time 0.
    double t = -1, x = 0, a = 0;
    ASSERT_EQ(std::sscanf(lines[1].c_str(), "%*u,%lf,%*f,,,,,%lf,%lf", &t, &x, &a), 3) << lines[1];
    EXPECT_EQ(t, 0);
    EXPECT_NEAR(x, d.leads.lead_in.front().x_mm, 1e-6);
    EXPECT_NEAR(a, d.leads.lead_in.front().a_deg, 1e-6);
    // The cut's rows are the old file's but for index, t, s, the closing step and the column:
    // beta .. pipe and the pulse positions (fields 3 .. 11) alike.
    std::vector<std::string> oldLines;
    const std::string old = profilePathCsv(d.cut, d.schedule);
    for (size_t at = 0, nl; (nl = old.find('\n', at)) != std::string::npos; at = nl + 1)
        oldLines.push_back(old.substr(at, nl - at));
    ASSERT_EQ(oldLines.size(), 1 + nCut);
    auto fields = [](const std::string& l, int from, int to) {
        size_t b = 0;
        for (int k = 0; k < from; ++k)
            b = l.find(',', b) + 1;
        size_t e = b;
        for (int k = from; k <= to; ++k)
            e = l.find(',', e) + 1;
        return l.substr(b, e - b);
    };
    for (size_t i = 0; i < nCut; ++i)
        EXPECT_EQ(fields(lines[1 + nIn + i], 3, 11), fields(oldLines[1 + i], 3, 11)) << i;
    std::printf("[ figures  ] path.csv: %zu lead-in, %zu cut, %zu lead-out rows\n", nIn, nCut,
                nOut);
}

// The shipped lead-in job on the simulated rig (fast clock): lit at the pierce point, the
// pierce delay, the whole path to Completed.
TEST(ProfileLeadEngine, LeadInJobRunsToCompletedOnTheSimulatedRig) {
    const Job job = leadInJob();
    const MachinePlan plan = ProfileCutterModule().plan(job, {}, {});
    ASSERT_TRUE(plan.ok()) << plan.outcome.message;
    std::string error;
    auto rig = makeSimulatedRig(job, *plan.program, &error);
    ASSERT_TRUE(rig) << error;
    EngineConfig c;
    c.clock = ClockMode::AsFastAsPossible;
    c.spec = job.engine;
    c.spec.runs_dir.clear();
    rig->configure(c);
    MotionEngine engine(rig->devices(), c);
    TelemetrySample last;
    double maxProgress = 0, arcAt = -1, movedAt = -1;
    JointVector atArc = JointVector::Zero();
    auto cycles = [&](std::uint64_t count, EngineState until) {
        EngineState s = engine.state();
        for (std::uint64_t done = 0; done < count && s != until; done += 50) {
            s = engine.runCycles(std::min<std::uint64_t>(50, count - done), until);
            TelemetrySample t;
            while (engine.popTelemetry(t)) {
                last = t;
                maxProgress = std::max(maxProgress, t.progress);
                if (arcAt < 0 && t.torch_on && t.process_ok) {
                    arcAt = t.time_s;
                    atArc = t.setpoint;
                } else if (arcAt >= 0 && movedAt < 0 && t.setpoint != atArc) {
                    movedAt = t.time_s;
                }
            }
        }
        return s;
    };
    ASSERT_TRUE(engine.load(plan.program));
    ASSERT_TRUE(engine.enable());
    ASSERT_EQ(cycles(1000, EngineState::Ready), EngineState::Ready);
    ASSERT_TRUE(engine.home());
    cycles(1, EngineState::Idle);
    ASSERT_EQ(cycles(200000, EngineState::Ready), EngineState::Ready);
    ASSERT_TRUE(engine.start());
    const auto limit =
        static_cast<std::uint64_t>((plan.program->cut_time_s + 60) / job.sim.period_s);
    ASSERT_EQ(cycles(limit, EngineState::Completed), EngineState::Completed);
    EXPECT_NEAR(maxProgress, 1.0, 1e-9);
    EXPECT_EQ(last.point_count, plan.program->point_count);
    // Lit at the pierce point (the lead-in's first point), then the pierce delay.
    ASSERT_GE(arcAt, 0);
    ASSERT_GE(movedAt, 0);
    const ProfilePoint& pierce = planData(plan).leads.lead_in.front();
    EXPECT_NEAR(atArc[0], deg2rad(pierce.a_deg), 1e-9);
    EXPECT_NEAR(atArc[1], pierce.x_mm, 1e-9);
    const double T = job.sim.period_s;
    EXPECT_GE(movedAt - arcAt, plan.program->pierce_s - 0.5 * T);
    EXPECT_LE(movedAt - arcAt, plan.program->pierce_s + 3 * T);
    TrackingReport report;
    ASSERT_TRUE(engine.lastRunReport(report));
    const double turn = static_cast<double>(profileCutterSpec(job).steps_per_rev_a) *
                        profileCutterSpec(job).pulses_per_step_a;
    // Open-loop steppers miss by their quantisation and one cycle of motion (at the chart's
    // speed, up to 1.1 v where a line lead meets the cut).
    const double v = 1.1 * job.cut.speed_mm_s, R = planData(plan).cut.work_radius_mm;
    EXPECT_LT(report.joints[0].max_abs, 360.0 / turn + rad2deg(v / R * T));
    EXPECT_LT(report.joints[1].max_abs, 2 * profileCutterSpec(job).mm_per_pulse_x + v * T);
    std::printf("[ figures  ] run: %.2f s path, %zu points, pierce %.3f s (measured %.3f s), "
                "A max err %.4f deg, X max err %.4f mm\n",
                plan.program->cut_time_s, plan.program->point_count, plan.program->pierce_s,
                movedAt - arcAt, report.joints[0].max_abs, report.joints[1].max_abs);
}

} // namespace
} // namespace cutcell
