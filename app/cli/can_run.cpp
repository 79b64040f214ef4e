#include "can_run.h"

#include "devices/canopen/canopen_master.h"
#include "devices/canopen/cell_safe_stop.h"
#include "devices/canopen/drive_simulator.h"
#include "devices/process/safe_shutdown.h"

#include "qt_app.h"

#include <chrono>
#include <cmath>
#include <ctime>
#include <memory>
#include <thread>

namespace cutcell::cli {
namespace {

using namespace cutcell::canopen;
using Clock = std::chrono::steady_clock;

std::string faultText(CanOpenMaster& m, int axis, const DriveFeedback& fb);

// One cycle of the lock-step runner, and its one supervision: once the drives are enabled,
// every cycle of every phase (approach, settling, cut) checks every drive, so a fault anywhere
// stops the run at the next SYNC (the engine path does the same in its cycle).
class Cycler {
  public:
    Cycler(CanOpenMaster& m, double period, bool realtime)
        : m_(m), period_(period), realtime_(realtime) {
        clock_gettime(CLOCK_MONOTONIC, &next_);
    }

    // From now on every step requires every drive Enabled; `phase` names the step in errors.
    void supervise(const char* phase) { phase_ = phase; }

    // Writes the set-points, sends one SYNC and waits for every node's TPDO of that SYNC.
    bool step(const JointVector& targets, std::string& error) {
        if (const int sig = SafeShutdown::requestedSignal()) {
            error = std::string("stopped by ") + SafeShutdown::signalName(sig);
            return false;
        }
        for (int i = 0; i < m_.driveCount(); ++i)
            m_.drive(i)->write(targets[i]);
        if (realtime_) {
            next_.tv_nsec += static_cast<long>(period_ * 1e9);
            while (next_.tv_nsec >= 1'000'000'000) {
                next_.tv_nsec -= 1'000'000'000;
                ++next_.tv_sec;
            }
            clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next_, nullptr);
        }
        const std::uint64_t expected = ++sent_;
        m_.sync();
        const auto deadline = Clock::now() + std::chrono::milliseconds(500);
        while (m_.cyclesCompleted() < expected) {
            if (Clock::now() > deadline) {
                error = "no process data (TPDO) from every node within 500 ms of SYNC " +
                        std::to_string(expected);
                return false;
            }
            std::this_thread::sleep_for(std::chrono::microseconds(20));
        }
        return supervised(error);
    }

    bool supervised(std::string& error) {
        if (!phase_) return true;
        for (int i = 0; i < m_.driveCount(); ++i) {
            const DriveFeedback fb = m_.drive(i)->read(0);
            if (fb.state == DriveState::Enabled) continue;
            error = (fb.state == DriveState::Fault
                         ? faultText(m_, i, fb)
                         : "axis " + std::to_string(i) + " left Operation Enabled (now " +
                               toString(fb.state) + ")") +
                    " during the " + phase_;
            return false;
        }
        return true;
    }
    void skipTo(std::uint64_t sent) { sent_ = sent; }

    JointVector read(std::array<DriveFeedback, kAxisCount>& fb) {
        JointVector q = JointVector::Zero();
        for (int i = 0; i < m_.driveCount(); ++i) {
            fb[static_cast<size_t>(i)] = m_.drive(i)->read(0);
            q[i] = fb[static_cast<size_t>(i)].position;
        }
        return q;
    }

  private:
    CanOpenMaster& m_;
    double period_;
    bool realtime_;
    const char* phase_ = nullptr;
    timespec next_{};
    std::uint64_t sent_ = 0;
};

std::string faultText(CanOpenMaster& m, int axis, const DriveFeedback& fb) {
    const CanBusSnapshot s = m.snapshot();
    const CanNodeSnapshot& n = s.nodes[static_cast<size_t>(axis)];
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", fb.fault_code);
    std::string why = !n.fault_text.empty()       ? n.fault_text
                      : !n.last_emcy_text.empty() ? n.last_emcy_text
                                                  : "";
    return "axis " + std::to_string(axis) + " (node " + std::to_string(n.node) +
           ") in Fault, code " + code + (why.empty() ? "" : ": " + why);
}

} // namespace

CanRunResult runCutOverCan(const Job& job, const CutPlan& plan, const CanRunOptions& o) {
    CanRunResult r;
    const auto t0 = Clock::now();
    const auto app = ensureQCoreApplication();

    const double T = o.period_s > 0 ? o.period_s : job.sim.period_s;
    CanOpenMasterConfig mc = masterConfigFromJob(job, T, kAxisCount);
    if (!o.plugin.empty()) mc.plugin = QString::fromStdString(o.plugin);
    if (!o.interface.empty()) mc.interface = QString::fromStdString(o.interface);
    mc.sync = SyncSource::External;

    std::unique_ptr<DriveSimulator> sim;
    if (o.in_process_simulator) {
        DriveSimulatorConfig sc;
        sc.plugin = mc.plugin;
        sc.interface = mc.interface;
        sc.nodes = nodesFromJob(
            job, {job.devices.node_ids.begin(), job.devices.node_ids.begin() + kAxisCount});
        sim = std::make_unique<DriveSimulator>(sc);
        if (!sim->start()) {
            r.error = "drive simulator: " + sim->errorText().toStdString();
            return r;
        }
    }
    CanOpenMaster master(mc);
    // Any ending (signal, std::terminate) first disables every drive on the bus, then logs.
    SafeShutdown::install();
    const SafeShutdown::Registration safeStop = SafeShutdown::add([&](const std::string& why) {
        safeStopCanCell(nullptr, &master, why, "cutcell-cli simulate", "");
    });
    if (!master.start(&r.error)) return r;
    auto fail = [&](const std::string& why) {
        master.emergencyStop(false);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        r.error = why;
        return r;
    };
    const auto bootDeadline = Clock::now() + std::chrono::seconds(5);
    while (!master.allOperational()) {
        if (Clock::now() > bootDeadline) {
            std::string why = "not every node became operational within 5 s";
            for (const CanNodeSnapshot& n : master.snapshot().nodes)
                if (!n.configured)
                    why += "; node " + std::to_string(n.node) + ": " +
                           (n.fault_text.empty() ? "no answer" : n.fault_text);
            return fail(why);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    Cycler cycler(master, T, o.realtime);
    cycler.skipTo(master.cyclesSent());
    std::array<DriveFeedback, kAxisCount> fb{};
    JointVector q = cycler.read(fb);

    // Enable: hold the actual positions until every drive reports Enabled.
    for (int i = 0; i < master.driveCount(); ++i)
        master.drive(i)->activate();
    for (int k = 0;; ++k) {
        q = cycler.read(fb);
        bool all = true;
        for (int i = 0; i < kAxisCount; ++i) {
            if (fb[static_cast<size_t>(i)].state == DriveState::Fault)
                return fail(faultText(master, i, fb[static_cast<size_t>(i)]));
            all = all && fb[static_cast<size_t>(i)].state == DriveState::Enabled;
        }
        if (all) break;
        if (k * T > 2.0) return fail("the drives did not reach Operation Enabled within 2 s");
        if (!cycler.step(q, r.error)) return fail(r.error);
    }

    cycler.supervise("approach");
    // Approach the start of the cut (smooth cosine move at the homing speed), then settle.
    const JointVector from = q;
    const JointVector start = plan.spline.evaluate(0).q;
    const double speed = deg2rad(job.engine.home_speed_deg_s);
    const double approach = std::max(0.5, (start - from).cwiseAbs().maxCoeff() / speed * 1.5);
    const long approachSteps = static_cast<long>(std::ceil((approach + 0.3) / T));
    for (long k = 0; k < approachSteps; ++k) {
        const double s = std::min(1.0, static_cast<double>(k + 1) * T / approach);
        if (!cycler.step(from + (start - from) * (0.5 - 0.5 * std::cos(kPi * s)), r.error))
            return fail(r.error);
    }

    // The cut. The position reported at SYNC n answers the target written before SYNC n-1;
    // a target written now (after SYNC n's feedback) goes out before SYNC n+1 and is reached
    // at SYNC n+2: the set-points lead by two periods.
    const PipeRobot robot(job.dh);
    TrackingStats stats(robot), cruise(robot);
    const SpeedProfile profile(plan.length_mm, job.cut.speed_mm_s, job.cut.ramp_s);
    const double ramp = profile.duration() - plan.length_mm / job.cut.speed_mm_s;
    const double simulated = std::max(job.sim.duration_s, plan.cut_time_s);
    const long steps = static_cast<long>(std::ceil(simulated / T - 1e-9));
    cycler.supervise("cut");
    for (int lead = 0; lead < 2; ++lead)
        if (!cycler.step(plan.spline.evaluate(lead * T).q, r.error)) return fail(r.error);
    for (long k = 0; k <= steps; ++k) {
        const double t = static_cast<double>(k) * T;
        q = cycler.read(fb); // supervised by the step that brought this feedback
        const JointVector ref = plan.spline.evaluate(t).q;
        stats.add(ref, q);
        // The torque in this TPDO was applied over the cycle before it (simulateCut's order).
        if (k > 0)
            for (int i = 0; i < kAxisCount; ++i)
                stats.addTorqueFraction(std::fabs(fb[static_cast<size_t>(i)].torque_ratio));
        if (t >= ramp && t <= plan.cut_time_s - ramp) cruise.add(ref, q);
        if (!cycler.step(plan.spline.evaluate(t + 2 * T).q, r.error)) return fail(r.error);
    }
    for (int i = 0; i < master.driveCount(); ++i)
        master.drive(i)->deactivate();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));

    r.report.method = toString(job.method);
    r.report.reachable = plan.reachable;
    r.report.length_mm = plan.length_mm;
    r.report.cut_time_s = plan.cut_time_s;
    r.report.max_direction_deviation_deg = plan.max_deviation_deg;
    stats.fill(r.report);
    cruise.fillCruise(r.report);
    r.report.simulated_s = static_cast<double>(steps) * T;
    r.report.steps = steps;
    const MasterStats ms = master.stats();
    r.sync_jitter_us_p99 = ms.sync_jitter_us_p99;
    r.frames_tx = ms.frames_tx;
    r.frames_rx = ms.frames_rx;
    master.stop();
    r.wall_s = std::chrono::duration<double>(Clock::now() - t0).count();
    r.ok = true;
    return r;
}

} // namespace cutcell::cli

// ---- cutcell-cli simulate JOB --devices canopen ------------------------------------------

#include "cli_commands.h"
#include "core/job/job_io.h"
#include "core/json/json.h"

namespace cutcell::cli {

bool usesCanOpen(const std::string& devices, const Job& job) {
    if (devices.empty()) return job.devices.kind == DeviceKind::CanOpen;
    return devices == "canopen";
}

int runSimulateCan(const Job& job, const CutPlan& plan, const SimulateOptions& options) {
    const CanRunOptions& o = options.devices.can;
    const CanRunResult r = runCutOverCan(job, plan, o);
    if (!r.ok) {
        std::fprintf(stderr, "cutcell-cli simulate over CANopen: %s\n", r.error.c_str());
        const int sig = SafeShutdown::requestedSignal();
        return sig ? 128 + sig : kFailure;
    }
    json::Value doc = reportToJson(r.report);
    const double T = o.period_s > 0 ? o.period_s : job.sim.period_s;
    doc.set("devices",
            json::Object{
                {"kind", "canopen"},
                {"can_plugin", o.plugin.empty() ? job.devices.can_plugin : o.plugin},
                {"can_interface", o.interface.empty() ? job.devices.can_interface : o.interface},
                {"period_s", T},
                {"clock", o.realtime ? "realtime" : "fast"},
                {"frames_tx", static_cast<double>(r.frames_tx)},
                {"frames_rx", static_cast<double>(r.frames_rx)},
                {"wall_s", r.wall_s}});
    if (o.realtime) doc.asObject().back().second.set("sync_jitter_us_p99", r.sync_jitter_us_p99);
    const std::string text = json::write(doc);
    const std::string& reportFile = options.report;
    if (const int rc = emitReport(reportFile, text, "simulate"); rc != kOk || reportFile.empty())
        return rc;
    std::printf("%s method over CANopen (%s, period %.1f ms): report written to %s\n",
                r.report.method.c_str(), o.realtime ? "real time" : "lock-step", T * 1e3,
                reportFile.c_str());
    return kOk;
}

} // namespace cutcell::cli
