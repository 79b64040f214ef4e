// The pipe robot's torch height control in the motion engine (issue 24) on the simulated cell:
// the arc voltage comes from the simulated arc over an out-of-round pipe mounted off-centre
// (devices/machines/pipe_robot/simulated_arc_voltage.*), the THC corrects the arm's set-point
// along the torch axis each cycle. The acceptance: on a pipe with 2 mm ovality the standoff
// error stays within +-0.2 mm with the THC on (after it settled) and is reported at ~+-1 mm with
// it off (summary figures and telemetry).
#include "core/engine/motion_engine.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"
#include "core/process/torch_height.h"
#include "devices/machines/sim_rig_registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace cutcell::test {
namespace {

constexpr double kSettleAllowanceS = 0.25; // as the THC model's own acceptance test

struct ThcRun {
    TrackingReport report;
    StandoffStats moving;  // telemetry: the path moving with the arc on
    StandoffStats settled; // ... from the THC's activation + the allowance, while it is Active
    double activation_s = -1;
    double maxCorrection = 0;
    long held = 0; // samples in anti-dive or settling after activation
    std::string log;
};

// The shipped THC job (the plasma job's DN40 branch end on a pipe with 2 mm ovality and a
// 0.5 mm run-out toward 20 deg), or (hole) the shipped plasma job's hole on the same pipe; each
// read from its file, so the chart picks the speed for the wall cut.
Job thcJob(bool thc, bool hole) {
    const std::string dir = std::string(CUTCELL_SOURCE_DIR) + "/resources/jobs/";
    Job job = loadJobFile(dir + (hole ? "plasma_hole_job.json" : "plasma_thc_job.json"));
    if (hole)
        job.process.torch_height = loadJobFile(dir + "plasma_thc_job.json").process.torch_height;
    EXPECT_TRUE(job.process.torch_height.used);
    EXPECT_EQ(job.process.torch_height.ovality_mm, 2);
    job.process.torch_height.thc = thc;
    return job;
}

std::string drainEvents(MotionEngine& e) {
    std::string s;
    EngineEvent ev;
    while (e.popEvent(ev))
        s += std::string(ev.text.data()) + "\n";
    return s;
}

ThcRun runThc(const Job& job) {
    ThcRun r;
    const MachineModule* m = findMachine(job.machine);
    const MachinePlan plan = m->plan(job, {});
    EXPECT_TRUE(plan.ok()) << plan.outcome.message;
    if (!plan.ok()) return r;
    std::string error;
    const std::unique_ptr<MachineSimRig> rig = makeSimulatedRig(job, *plan.program, &error);
    EXPECT_TRUE(rig) << error;
    if (!rig) return r;
    EngineConfig c;
    c.clock = ClockMode::AsFastAsPossible;
    c.spec = job.engine;
    c.spec.runs_dir.clear();
    rig->configure(c);
    MotionEngine engine(rig->devices(), c);
    engine.load(plan.program);
    engine.enable();
    engine.runCycles(2000, EngineState::Ready);
    engine.home();
    engine.runCycles(1, EngineState::Idle);
    engine.runCycles(200000, EngineState::Ready);
    engine.start();
    TelemetrySample t;
    for (int i = 0; i < 100000 && engine.state() != EngineState::Completed; ++i) {
        engine.runCycles(20, static_cast<EngineState>(255));
        while (engine.popTelemetry(t)) {
            const ProcessSignals& p = t.process;
            if (!p.present || !p.arc_ok || t.state != EngineState::Running) continue;
            const auto state = static_cast<ThcState>(p.thc_state);
            if (state == ThcState::Active && r.activation_s < 0) r.activation_s = t.time_s;
            if (state == ThcState::Pierce) continue;
            r.moving.add(p.height_error_mm);
            r.maxCorrection = std::max(r.maxCorrection, std::fabs(p.correction_mm));
            if (r.activation_s >= 0 && t.time_s >= r.activation_s + kSettleAllowanceS) {
                if (state == ThcState::Active)
                    r.settled.add(p.height_error_mm);
                else
                    ++r.held;
            }
        }
        r.log += drainEvents(engine);
    }
    EXPECT_EQ(engine.state(), EngineState::Completed) << r.log;
    EXPECT_TRUE(engine.lastRunReport(r.report));
    return r;
}

void print(const char* what, const ThcRun& r) {
    const TorchHeightFigures& h = r.report.torch_height;
    std::printf("%s: telemetry moving max|err| %.4f mm (%.4f .. %.4f, rms %.4f, %ld samples); "
                "from activation %.3f s + %.2f s: max|err| %.6f mm (rms %.4f, %ld samples, %ld "
                "held); max|correction| %.4f mm\n"
                "  summary: thc %s, max|err| %.4f (%.4f .. %.4f, rms %.4f, %ld samples), while "
                "active %.4f mm (%ld samples), voltage %.2f .. %.2f V\n",
                what, r.moving.max_abs_mm, r.moving.min_mm, r.moving.max_mm, r.moving.rms(),
                r.moving.count, r.activation_s, kSettleAllowanceS, r.settled.max_abs_mm,
                r.settled.rms(), r.settled.count, r.held, r.maxCorrection, h.thc_on ? "on" : "off",
                h.max_abs_error_mm, h.min_error_mm, h.max_error_mm, h.rms_error_mm, h.samples,
                h.active_max_abs_error_mm, h.active_samples, h.min_voltage_v, h.max_voltage_v);
}

} // namespace

// The branch end: its pipe turns a whole revolution under the torch, so the THC sees the
// whole out-of-roundness (THC off: -1.0 .. +0.56 mm by the geometry: torch_height_test.cpp).
TEST(RobotThcEngine, BranchEndOnAnOvalPipeOffAboutOneMillimetreOnWithinPointTwo) {
    const ThcRun off = runThc(thcJob(false, false));
    const ThcRun on = runThc(thcJob(true, false));
    print("THC off", off);
    print("THC on ", on);
    // Off: measured and reported, never corrected.
    ASSERT_TRUE(off.report.torch_height.valid);
    EXPECT_FALSE(off.report.torch_height.thc_on);
    EXPECT_EQ(off.maxCorrection, 0);
    EXPECT_GE(off.report.torch_height.max_abs_error_mm, 0.8);
    EXPECT_LE(off.report.torch_height.max_abs_error_mm, 1.2);
    EXPECT_LT(off.report.torch_height.min_error_mm, -0.8); // the torch too low at the major axis
    EXPECT_GT(off.report.torch_height.max_error_mm, 0.3);  // and too high beside it
    // On: within 0.2 mm once settled; it corrected about the pipe's own error.
    ASSERT_TRUE(on.report.torch_height.valid);
    EXPECT_TRUE(on.report.torch_height.thc_on);
    EXPECT_GT(on.activation_s, 0);
    EXPECT_GT(on.settled.count, 1000);
    EXPECT_LE(on.settled.max_abs_mm, 0.2);
    EXPECT_LE(on.report.torch_height.active_max_abs_error_mm,
              std::max(on.settled.max_abs_mm, 0.2) + 0.6); // includes the settle transient
    EXPECT_GE(on.maxCorrection, 0.5);
}

// The shipped hole job: the main pipe turns only through the hole's +-25 deg under the torch.
TEST(RobotThcEngine, HoleOnAnOvalPipeIsHeldWithinPointTwo) {
    const ThcRun off = runThc(thcJob(false, true));
    const ThcRun on = runThc(thcJob(true, true));
    print("hole THC off", off);
    print("hole THC on ", on);
    EXPECT_GT(off.report.torch_height.max_abs_error_mm, 0.2); // the THC has something to do
    EXPECT_GT(on.settled.count, 500);
    EXPECT_LE(on.settled.max_abs_mm, 0.2);
}

} // namespace cutcell::test
