// Torch height control, simulated (issue 24): the actual pipe surface (ovality, run-out, taper)
// and the THC loop on it. The surface checks recompute the ellipse themselves; the acceptance
// test runs a pipe under the torch for more than a turn at 1 kHz with THC off and on.
#include "core/process/pipe_surface.h"
#include "core/process/torch_height.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

using namespace cutcell;

namespace {

// Independent of the library: the distance of a pipe-frame point from the pipe's centre minus
// the ellipse's radius in that direction (0 on the surface).
double radialMiss(const PipeDefects& d, const Vec3& p) {
    const double R = d.radius_mm + d.taper_mm_per_m / 2000 * p.z();
    const double a = R + d.ovality_mm / 4, b = R - d.ovality_mm / 4;
    const double e = d.runout_mm, pe = deg2rad(d.runout_deg), pm = deg2rad(d.major_axis_deg);
    const double wx = p.x() - e * std::cos(pe), wy = p.y() - e * std::sin(pe);
    const double ang = std::atan2(wy, wx) - pm;
    const double rEll = a * b / std::hypot(b * std::cos(ang), a * std::sin(ang));
    return std::hypot(wx, wy) - rEll;
}

PipeDefects randomDefects(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    PipeDefects d;
    d.radius_mm = 10 + 290 * u(rng);
    d.ovality_mm = 0.2 * d.radius_mm * u(rng); // up to 10 % of the diameter
    d.major_axis_deg = 360 * u(rng);
    d.runout_mm = 0.1 * d.radius_mm * u(rng);
    d.runout_deg = 360 * u(rng);
    d.taper_mm_per_m = 40 * u(rng) - 20;
    return d;
}

// A unit direction within maxDeg of n (unit), uniformly around it.
Vec3 directionNear(std::mt19937& rng, const Vec3& n, double maxDeg) {
    std::uniform_real_distribution<double> u(0, 1);
    const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    const double off = deg2rad(maxDeg) * u(rng), around = 2 * kPi * u(rng);
    return std::cos(off) * n + std::sin(off) * (std::cos(around) * t1 + std::sin(around) * t2);
}

} // namespace

TEST(PipeSurface, PerfectPipeIsTheCylinderExactly) {
    const PipeDefects d{.radius_mm = 57.15};
    const ActualPipeSurface s(d);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 1000; ++i) {
        const double z = 200 * u(rng), phi = 4 * kPi * u(rng);
        ASSERT_EQ(s.radiusAt(z, phi), 57.15);
        const Vec3 p(57.15 * std::cos(phi), 57.15 * std::sin(phi), z);
        const SurfaceHit radial = s.alongLine(p, -Vec3(p.x(), p.y(), 0).normalized());
        ASSERT_TRUE(radial.ok);
        ASSERT_NEAR(radial.s_mm, 0, 1e-12);
    }
}

TEST(PipeSurface, OvalityIsDmaxMinusDmin) {
    std::mt19937 rng(2);
    for (int k = 0; k < 50; ++k) {
        PipeDefects d = randomDefects(rng);
        d.runout_mm = 0; // diameters through the pipe's own centre
        d.taper_mm_per_m = 0;
        const ActualPipeSurface s(d);
        double dMax = 0, dMin = 1e300;
        const int n = 7200;
        for (int i = 0; i <= n; ++i) { // the major and minor axes are among the samples
            const double phi = deg2rad(d.major_axis_deg) + kPi * i / n;
            const double dia = s.radiusAt(0, phi) + s.radiusAt(0, phi + kPi);
            dMax = std::max(dMax, dia);
            dMin = std::min(dMin, dia);
        }
        ASSERT_NEAR(dMax - dMin, d.ovality_mm, 1e-9 * d.radius_mm) << "R " << d.radius_mm;
        ASSERT_NEAR(dMax + dMin, 4 * d.radius_mm, 1e-9 * d.radius_mm); // mean diameter = 2R
    }
}

TEST(PipeSurface, RunoutIsTotalIndicatorReadingOverTwo) {
    const PipeDefects d{.radius_mm = 57.15, .runout_mm = 0.5, .runout_deg = 30};
    const ActualPipeSurface s(d);
    double hi = -1e300, lo = 1e300;
    for (int i = 0; i < 3600; ++i) {
        const double r = s.radiusAt(0, deg2rad(30 + 0.1 * i));
        hi = std::max(hi, r);
        lo = std::min(lo, r);
    }
    EXPECT_NEAR(hi - lo, 2 * 0.5, 1e-12);
    EXPECT_NEAR(s.radiusAt(0, deg2rad(30)), 57.15 + 0.5, 1e-12);
}

TEST(PipeSurface, LineCrossingLiesOnTheSurface) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    int maxIterations = 0;
    for (int k = 0; k < 20000; ++k) {
        const PipeDefects d = randomDefects(rng);
        const ActualPipeSurface s(d);
        const double phi = 2 * kPi * u(rng), z = 200 * u(rng) - 100;
        const Vec3 p(d.radius_mm * std::cos(phi), d.radius_mm * std::sin(phi), z);
        const Vec3 inward(-std::cos(phi), -std::sin(phi), 0);
        const Vec3 dir = directionNear(rng, inward, 60);
        const SurfaceHit h = s.alongLine(p, dir);
        ASSERT_TRUE(h.ok) << k;
        ASSERT_LT(std::fabs(radialMiss(d, h.point)), 1e-9) << k;
        ASSERT_LT((h.point - (p + h.s_mm * dir)).norm(), 1e-12 * (1 + d.radius_mm));
        maxIterations = std::max(maxIterations, h.iterations);
    }
    std::printf("line crossing: at most %d Newton steps\n", maxIterations);
    EXPECT_LE(maxIterations, 10);
}

TEST(PipeSurface, RadialLineAgreesWithTheRadialFunction) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(0, 1);
    for (int k = 0; k < 2000; ++k) {
        const PipeDefects d = randomDefects(rng);
        const ActualPipeSurface s(d);
        const double phi = 2 * kPi * u(rng), z = 100 * u(rng) - 50;
        const Vec3 p(d.radius_mm * std::cos(phi), d.radius_mm * std::sin(phi), z);
        const SurfaceHit h = s.alongLine(p, Vec3(-std::cos(phi), -std::sin(phi), 0));
        ASSERT_TRUE(h.ok);
        ASSERT_NEAR(h.s_mm, d.radius_mm - s.radiusAt(z, phi), 1e-9);
        ASSERT_NEAR(s.level(h.point), 0, 1e-9);
    }
}

TEST(PipeSurface, GrazingLineIsNotIntersected) {
    const ActualPipeSurface s(PipeDefects{.radius_mm = 50, .ovality_mm = 1});
    const Vec3 p(50, 0, 0);
    const double off = deg2rad(85);
    EXPECT_FALSE(s.alongLine(p, Vec3(-std::cos(off), std::sin(off), 0)).ok);
    EXPECT_TRUE(s.alongLine(p, Vec3(-std::cos(deg2rad(60)), std::sin(deg2rad(60)), 0)).ok);
}

TEST(PipeSurface, RefusalsNameFieldValueUnitAndLimit) {
    PipeDefects d{.radius_mm = 57.15, .ovality_mm = 12};
    Outcome o = checkPipeDefects(d);
    ASSERT_FALSE(o.ok());
    EXPECT_EQ(o.message,
              "ovality_mm = 12 mm is outside 0 .. 11.43 mm (10 % of the diameter 114.3 mm)");
    d.ovality_mm = 2;
    d.runout_mm = 6;
    o = checkPipeDefects(d);
    EXPECT_EQ(o.message,
              "runout_mm = 6 mm is outside 0 .. 5.715 mm (a tenth of the radius 57.15 mm)");
    d.runout_mm = -0.1;
    EXPECT_FALSE(checkPipeDefects(d).ok());
    d.runout_mm = 0;
    d.taper_mm_per_m = 25;
    EXPECT_EQ(checkPipeDefects(d).message, "taper_mm_per_m = 25 mm/m is outside -20 .. 20 mm/m");
    d.taper_mm_per_m = 0;
    d.radius_mm = 0;
    EXPECT_FALSE(checkPipeDefects(d).ok());
    EXPECT_THROW(ActualPipeSurface{d}, std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// The THC on a rotating pipe.

namespace {

// The cell of the default job (resources/jobs/default_job.json): main pipe OD 114.3 mm
// (R = 57.15 mm), wall 6.02 mm. That job cuts by oxy-fuel at 4.397 mm/s; the THC is a plasma
// process, so the cut speed and the pierce delay are the shipped plasma chart's for the wall:
// mild steel, Powermax65/85 65 A shielded, 6.02 mm -> 2541.5 mm/min (42.4 mm/s, 8.5 s a turn),
// pierce 0.5 s. The job's 0.5 s cosine ramp starts the motion.
constexpr double kR = 57.15, kWall = 6.02, kRampS = 0.5, kT = 0.001;

ThcProcess chartProcess() {
    const CutPick pick = pickCutRow(shippedCutCharts(), CutProcess::Plasma, "mild_steel",
                                    "Powermax65/85 65A shielded", kWall);
    EXPECT_TRUE(pick.ok()) << pick.outcome.message;
    return thcProcessFor(*pick.chart, pick.row);
}

struct RunResult {
    StandoffStats cutting;     // every cycle the path moves
    StandoffStats afterSettle; // from the THC's first activation + settle allowance on
    double activation_s = -1;  // first cycle Active (THC on)
    double errorAtActivation = 0;
    double settle_s = 0; // from activation to the last |error| > 0.2 mm
    double turns = 0;    // pipe revolutions while moving
};

// A torch at the top of the pipe (machine angle 90 deg), square to the nominal surface, its
// tip at the cut height above the nominal cylinder; the pipe turns under it at the path speed
// for `turns` revolutions. The standoff is read before this cycle's THC command (the sensor
// sees the present state), then the THC and the torch axis step.
RunResult runPipe(const PipeDefects& defects, const ThcProcess& proc, ThcSpec thc,
                  const ArcModelSpec& arcSpec, double startChuckDeg, double turns = 1.25,
                  double settleAllowance_s = 0.25) {
    const ActualPipeSurface surface(defects);
    ArcModel arc(arcSpec);
    TorchAxis axis(TorchAxisSpec{});
    ThcController ctl(thc);
    RunResult r;
    const double theta = kPi / 2, v = proc.cut_speed_mm_s, pierce = proc.pierce_delay_s;
    double s = 0; // path length moved
    for (long i = 0;; ++i) {
        const double t = static_cast<double>(i) * kT;
        const bool moving = t >= pierce;
        const double tm = t - pierce;
        const double speed = !moving       ? 0
                             : tm < kRampS ? v * 0.5 * (1 - std::cos(kPi * tm / kRampS))
                                           : v;
        const double chuck = deg2rad(startChuckDeg) + s / kR;
        const double phi = theta - chuck;
        const Vec3 p(kR * std::cos(phi), kR * std::sin(phi), 0);
        const SurfaceHit hit = surface.alongLine(p, Vec3(-std::cos(phi), -std::sin(phi), 0));
        EXPECT_TRUE(hit.ok);
        const double standoff = proc.cut_height_mm + hit.s_mm - axis.position();
        const double error = standoff - proc.cut_height_mm;
        const ThcOutput& out = ctl.update({.period_s = kT,
                                           .arc_ok = true,
                                           .moving = moving,
                                           .arc_voltage_v = arc.voltage(standoff),
                                           .path_speed_mm_s = speed,
                                           .cut_speed_mm_s = v});
        axis.step(out.correction_mm, kT);
        if (moving) r.cutting.add(error);
        if (out.state == ThcState::Active && r.activation_s < 0) {
            r.activation_s = t;
            r.errorAtActivation = error;
        }
        if (r.activation_s >= 0 && t >= r.activation_s + settleAllowance_s)
            r.afterSettle.add(error);
        if (r.activation_s >= 0 && std::fabs(error) > 0.2) r.settle_s = t - r.activation_s;
        s += speed * kT;
        if (s >= turns * 2 * kPi * kR) break;
    }
    r.turns = s / (2 * kPi * kR);
    return r;
}

ThcSpec specFor(const ThcProcess& proc, bool on) {
    ThcSpec s;
    s.enabled = on;
    s.setpoint_v = proc.arc_voltage_v; // the chart's voltage at the cut height
    s.volts_per_mm = proc.volts_per_mm;
    return s;
}

ArcModelSpec arcFor(const ThcProcess& proc) {
    return {.arc_voltage_v = proc.arc_voltage_v,
            .cut_height_mm = proc.cut_height_mm,
            .volts_per_mm = proc.volts_per_mm};
}

// The acceptance pipe. Ovality is the standard D_max - D_min = 2 mm, which moves the surface
// under a radial torch by only +-0.5 mm (the semi-axes are R +- O/4). The issue's "~+-1 mm
// with THC off" then needs a second defect, as a real pipe in a chuck has: a run-out of
// e = 0.5 mm (an eccentric mount, TIR 1 mm) toward the major axis. Under the torch the surface
// then rises by 0.5 cos 2x + 0.5 cos x to first order (x from the major axis): +1.0 mm at x = 0
// (exactly e + O/4: the torch stands 1 mm too low), -0.56 mm at cos x = -1/4 (too high), so
// THC off shows a standoff error from -1.0 to +0.56 mm, a peak of 1 mm.
PipeDefects acceptancePipe() {
    return {
        .radius_mm = kR, .ovality_mm = 2, .major_axis_deg = 20, .runout_mm = 0.5, .runout_deg = 20};
}

} // namespace

TEST(TorchHeight, ChartFiguresAndStatedDefaults) {
    const ThcProcess p = chartProcess();
    EXPECT_NEAR(p.cut_speed_mm_s, 2541.5 / 60, 1e-9);
    EXPECT_NEAR(p.pierce_delay_s, 0.5, 1e-12);
    // The shipped charts give no cut height, arc voltage nor slope: the stated defaults.
    EXPECT_FALSE(p.cut_height_from_chart || p.arc_voltage_from_chart || p.volts_per_mm_from_chart);
    EXPECT_EQ(p.volts_per_mm, kTypicalVoltsPerMm);

    CutChart chart;
    chart.volts_per_mm = 4.0;
    CutRow row;
    row.set(CutFigure::CutHeightMm, 2.0);
    row.set(CutFigure::ArcVoltageV, 132);
    row.set(CutFigure::CutSpeedMmMin, 600);
    const ThcProcess q = thcProcessFor(chart, row);
    EXPECT_TRUE(q.cut_height_from_chart && q.arc_voltage_from_chart && q.volts_per_mm_from_chart);
    EXPECT_EQ(q.volts_per_mm, 4.0);
    EXPECT_EQ(q.arc_voltage_v, 132);
    EXPECT_EQ(q.cut_speed_mm_s, 10);
    chart.volts_per_mm = 0; // "0 / absent": the default
    EXPECT_EQ(thcProcessFor(chart, row).volts_per_mm, kTypicalVoltsPerMm);
}

// THE ACCEPTANCE TEST (issue 24): 2 mm ovality (+ 0.5 mm run-out, see acceptancePipe), more
// than one turn at 1 kHz, from 8 start angles of the pipe. THC off: the peak standoff error is
// ~1 mm; THC on: within 0.2 mm from its activation (after the pierce and the arc-settle delay)
// plus a settle allowance of 0.25 s for the error the pipe made during the delay.
TEST(TorchHeight, AcceptanceOvalPipeOffAboutOneMillimetreOnWithinPointTwo) {
    const ThcProcess proc = chartProcess();
    double worstOff = 0, worstOn = 0, worstOnWhole = 0, worstActivation = 0, bestOff = 1e9;
    for (int k = 0; k < 8; ++k) {
        const double start = 45.0 * k;
        const RunResult off =
            runPipe(acceptancePipe(), proc, specFor(proc, false), arcFor(proc), start);
        const RunResult on =
            runPipe(acceptancePipe(), proc, specFor(proc, true), arcFor(proc), start);
        std::printf("start %5.1f deg: THC off max|err| %.4f mm (%.4f .. %.4f, rms %.4f); "
                    "THC on from %.3f s: err there %.4f, within 0.2 after %.3f s, whole cut max "
                    "%.4f, after settle max %.4f mm (rms %.4f), %.2f turns\n",
                    start, off.cutting.max_abs_mm, off.cutting.min_mm, off.cutting.max_mm,
                    off.cutting.rms(), on.activation_s, on.errorAtActivation, on.settle_s,
                    on.cutting.max_abs_mm, on.afterSettle.max_abs_mm, on.afterSettle.rms(),
                    on.turns);
        ASSERT_LE(on.settle_s, 0.25); // the allowance covers the error made during the delay
        // Not before the pierce and the arc-settle delay (its last cycle activates).
        ASSERT_GE(on.activation_s, proc.pierce_delay_s + 0.5 - kT - 1e-9);
        ASSERT_GE(on.afterSettle.count, static_cast<long>(2 * kPi * kR / proc.cut_speed_mm_s / kT));
        worstOff = std::max(worstOff, off.cutting.max_abs_mm);
        bestOff = std::min(bestOff, off.cutting.max_abs_mm);
        worstOn = std::max(worstOn, on.afterSettle.max_abs_mm);
        worstOnWhole = std::max(worstOnWhole, on.cutting.max_abs_mm);
        worstActivation = std::max(worstActivation, std::fabs(on.errorAtActivation));
        // THC off: both signs, as the geometry says (-1.0 .. +0.56 mm).
        EXPECT_LT(off.cutting.min_mm, -0.95);
        EXPECT_GT(off.cutting.max_mm, 0.45);
    }
    std::printf("ACCEPTANCE: THC off max|standoff error| %.4f .. %.4f mm over the start angles; "
                "THC on max|standoff error| after settle %.4f mm (whole cut %.4f, at activation "
                "up to %.4f)\n",
                bestOff, worstOff, worstOn, worstOnWhole, worstActivation);
    EXPECT_GE(bestOff, 0.8);
    EXPECT_LE(worstOff, 1.2);
    EXPECT_LE(worstOn, 0.2);
}

TEST(TorchHeight, HoldsThroughArcNoiseAndSlopeMismatch) {
    const ThcProcess proc = chartProcess();
    ThcSpec thc = specFor(proc, true);
    thc.lowpass_hz = 10;
    ArcModelSpec arc = arcFor(proc);
    arc.noise_v = 0.75; // LinuxCNC sim-torch's default cut noise
    arc.seed = 7;
    const RunResult noisy = runPipe(acceptancePipe(), proc, thc, arc, 0);
    std::printf("noise +-0.75 V, 10 Hz filter: max|err| after settle %.4f mm (rms %.4f)\n",
                noisy.afterSettle.max_abs_mm, noisy.afterSettle.rms());
    EXPECT_LE(noisy.afterSettle.max_abs_mm, 0.2);
    // The real slope is not the controller's: 4 and 10 V/mm (the sources' spread) against 7.5.
    // At 4 V/mm the loop gain is halved and the deadband, in mm, nearly doubled: the error
    // grows (calibrate volts_per_mm on the torch); 10 V/mm is the stability side.
    for (double kv : {4.0, 10.0}) {
        ArcModelSpec a = arcFor(proc);
        a.volts_per_mm = kv;
        const RunResult r = runPipe(acceptancePipe(), proc, specFor(proc, true), a, 90);
        std::printf("arc %.1f V/mm, THC assumes %.1f: max|err| after settle %.4f mm\n", kv,
                    proc.volts_per_mm, r.afterSettle.max_abs_mm);
        EXPECT_LE(r.afterSettle.max_abs_mm, kv < 7.5 ? 0.25 : 0.2);
    }
}

TEST(TorchHeight, HoldsDuringPierceAndWhenTheArcIsLost) {
    ThcController thc(ThcSpec{});
    const ThcSpec& s = thc.spec();
    ThcInput in{.period_s = kT,
                .arc_ok = true,
                .moving = false,
                .path_speed_mm_s = 0,
                .cut_speed_mm_s = 40};
    // Pierce: the torch stands at a pierce height well above the cut height (high voltage).
    in.arc_voltage_v = s.setpoint_v + 2.3 * s.volts_per_mm;
    for (int i = 0; i < 500; ++i) {
        const ThcOutput& o = thc.update(in);
        ASSERT_EQ(o.state, ThcState::Pierce);
        ASSERT_EQ(o.correction_mm, 0);
    }
    // Moving at the cut speed, 1 mm too high: nothing until the arc-settle delay is over.
    in.moving = true;
    in.path_speed_mm_s = 40;
    in.arc_voltage_v = s.setpoint_v + 1.0 * s.volts_per_mm;
    int cycles = 0;
    while (thc.update(in).state == ThcState::Settling) {
        ASSERT_EQ(thc.output().correction_mm, 0);
        ++cycles;
    }
    EXPECT_EQ(cycles, 499); // the 500th cycle after the start of motion is active
    EXPECT_EQ(thc.output().state, ThcState::Active);
    for (int i = 0; i < 50; ++i)
        thc.update(in);
    const double moved = thc.output().correction_mm;
    EXPECT_GT(moved, 0.05); // down, toward the material
    // The arc is lost: the voltage means nothing; the correction holds.
    in.arc_ok = false;
    in.arc_voltage_v = 0;
    for (int i = 0; i < 300; ++i) {
        const ThcOutput& o = thc.update(in);
        ASSERT_EQ(o.state, ThcState::ArcOff);
        ASSERT_EQ(o.correction_mm, moved);
        ASSERT_EQ(o.velocity_mm_s, 0);
    }
    // Re-lit: the arc settles again before the THC moves.
    in.arc_ok = true;
    in.arc_voltage_v = s.setpoint_v + 1.0 * s.volts_per_mm;
    EXPECT_EQ(thc.update(in).state, ThcState::Settling);
    EXPECT_EQ(thc.output().correction_mm, moved);
}

TEST(TorchHeight, AntiDiveFreezesOnASpeedDrop) {
    ThcController thc(ThcSpec{});
    const ThcSpec& s = thc.spec();
    ThcInput in{.period_s = kT,
                .arc_ok = true,
                .moving = true,
                .arc_voltage_v = s.setpoint_v + 0.5 * s.volts_per_mm,
                .path_speed_mm_s = 40,
                .cut_speed_mm_s = 40};
    for (int i = 0; i < 700; ++i)
        thc.update(in);
    ASSERT_EQ(thc.output().state, ThcState::Active);
    const double before = thc.output().correction_mm;
    ASSERT_GT(before, 0);
    // A corner: the path slows to 50 % and the arc voltage rises (a longer arc at low speed);
    // a THC that followed it would dive.
    in.path_speed_mm_s = 20;
    in.arc_voltage_v = s.setpoint_v + 10;
    for (int i = 0; i < 400; ++i) {
        const ThcOutput& o = thc.update(in);
        ASSERT_EQ(o.state, ThcState::AntiDive);
        ASSERT_EQ(o.correction_mm, before);
    }
    // At 89 % still held, at 90 % of the cut speed it corrects again.
    in.path_speed_mm_s = 0.89 * 40;
    EXPECT_EQ(thc.update(in).state, ThcState::AntiDive);
    in.path_speed_mm_s = 0.9 * 40;
    EXPECT_EQ(thc.update(in).state, ThcState::Active);
    for (int i = 0; i < 10; ++i)
        thc.update(in);
    EXPECT_GT(thc.output().correction_mm, before);
}

TEST(TorchHeight, LimitsVelocityAccelerationAndTravel) {
    ThcSpec spec;
    spec.delay_s = 0;
    ThcController thc(spec);
    // A void under the torch: the voltage jumps 100 V; the THC may not run away.
    ThcInput in{.period_s = kT,
                .arc_ok = true,
                .moving = true,
                .arc_voltage_v = spec.setpoint_v + 100,
                .path_speed_mm_s = 40,
                .cut_speed_mm_s = 40};
    double vPrev = 0;
    for (int i = 0; i < 3000; ++i) {
        const ThcOutput& o = thc.update(in);
        ASSERT_LE(std::fabs(o.velocity_mm_s), spec.max_velocity_mm_s + 1e-12);
        ASSERT_LE(std::fabs(o.velocity_mm_s - vPrev), spec.max_acceleration_mm_s2 * kT + 1e-9);
        ASSERT_LE(std::fabs(o.correction_mm), spec.max_correction_mm + 1e-12);
        vPrev = o.velocity_mm_s;
    }
    EXPECT_EQ(thc.output().correction_mm, spec.max_correction_mm);
    // Within the deadband nothing moves.
    ThcController quiet(spec);
    in.arc_voltage_v = spec.setpoint_v + 0.9 * spec.deadband_v;
    for (int i = 0; i < 1000; ++i)
        quiet.update(in);
    EXPECT_EQ(quiet.output().correction_mm, 0);
    // THC off: no correction, but the voltage's height error is still shown.
    spec.enabled = false;
    ThcController off(spec);
    in.arc_voltage_v = spec.setpoint_v + 7.5;
    const ThcOutput& o = off.update(in);
    EXPECT_EQ(o.state, ThcState::Disabled);
    EXPECT_EQ(o.correction_mm, 0);
    EXPECT_NEAR(o.height_error_mm, 7.5 / spec.volts_per_mm, 1e-12);
}

TEST(TorchHeight, TorchAxisFollowsWithLagWithinItsLimits) {
    TorchAxis axis(TorchAxisSpec{});
    for (int i = 0; i < 2000; ++i)
        axis.step(1.0, kT);
    EXPECT_NEAR(axis.position(), 1.0, 1e-6);
    axis.reset();
    double vPrev = 0;
    for (int i = 0; i < 100; ++i) {
        axis.step(4.0, kT);
        ASSERT_LE(std::fabs(axis.velocity()), 20 + 1e-12);
        ASSERT_LE(std::fabs(axis.velocity() - vPrev), 500 * kT + 1e-9);
        vPrev = axis.velocity();
    }
}

TEST(TorchHeight, SpecRefusalsNameFieldValueUnitAndLimit) {
    ThcSpec s;
    s.volts_per_mm = 0;
    EXPECT_EQ(checkThcSpec(s).message, "volts_per_mm = 0 V/mm is outside [0.1, 50] V/mm");
    EXPECT_THROW(ThcController{s}, std::invalid_argument);
    s = ThcSpec{};
    s.kp_per_s = 0;
    EXPECT_EQ(checkThcSpec(s).message, "kp_per_s = 0 1/s is outside (0, 1000] 1/s");
    ArcModelSpec a;
    a.noise_v = -1;
    EXPECT_EQ(checkArcModelSpec(a).message, "noise_v = -1 V is outside [0, 50] V");
    EXPECT_TRUE(checkTorchAxisSpec(TorchAxisSpec{}).ok());
}
