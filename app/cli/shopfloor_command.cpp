// cutcell-cli shopfloor: the cell's Sparkplug B edge node without the GUI (issue 26). Connects to
// the broker of the configuration file, publishes the cell (idle, or the job given with --run as
// the motion engine runs it on the simulated rig: state, progress, axes at <= 10 Hz, the run's
// figures at its end), and takes the network's commands: a job queued by NCMD is validated as a
// file opened by hand and kept in the queue (listed; headless, nobody starts it), a feed hold
// acts on the run, clear empties the queue. Ends with a clean NDEATH.
#include "cli_commands.h"
#include "engine_run.h"

#include "core/engine/motion_engine.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/shopfloor/telemetry_snapshot.h"
#include "devices/process/safe_shutdown.h"
#include "devices/shopfloor/mosquitto_link.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>
#include <vector>

namespace cutcell::cli {
namespace {

using SteadyClock = std::chrono::steady_clock;

// The network's commands, on the link's thread: the queue under a mutex, the hold as a flag the
// run's telemetry hook acts on.
class HeadlessCell final : public shopfloor::ShopfloorCommandSink {
  public:
    std::string queueJob(const std::string& text, const std::string& source) override {
        try {
            const Job job = parseJob(text);
            const std::vector<JobIssue> issues = validateJob(job);
            if (!issues.empty())
                return issues.front()
                    .message; // it names the key, the value, the unit and the limit
            std::lock_guard lock(mutex_);
            queue_.push_back({job.name, source});
            std::fprintf(stderr,
                         "shopfloor: job '%s' queued by %s (%zu waiting; start it at the "
                         "operator station)\n",
                         job.name.c_str(), source.c_str(), queue_.size());
            return {};
        } catch (const std::exception& e) {
            return e.what();
        }
    }
    void feedHold() override {
        hold_ = true;
        std::fprintf(stderr, "shopfloor: feed hold requested from the network\n");
    }
    void clearQueue() override {
        std::lock_guard lock(mutex_);
        queue_.clear();
    }
    std::uint32_t queueLength() const {
        std::lock_guard lock(mutex_);
        return static_cast<std::uint32_t>(queue_.size());
    }
    bool takeHold() { return hold_.exchange(false); }

  private:
    struct Queued {
        std::string name, source;
    };
    mutable std::mutex mutex_;
    std::vector<Queued> queue_;
    std::atomic<bool> hold_{false};
};

} // namespace

int runShopfloor(const ShopfloorOptions& o) {
    shopfloor::ShopfloorConfig config;
    try {
        config = shopfloor::loadShopfloorConfig(o.config);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "shopfloor: %s\n", e.what());
        return kInvalidJob;
    }
    Job job;
    const MachineModule* module = nullptr;
    MachinePlan plan;
    if (!o.run.empty()) {
        try {
            job = loadJobFile(o.run);
        } catch (const JobFileError& e) {
            std::fprintf(stderr, "shopfloor: %s\n", e.what());
            return kFailure;
        } catch (const JobError& e) {
            std::fprintf(stderr, "shopfloor: %s\n", e.what());
            return kInvalidJob;
        }
        if (const auto issues = validateJob(job); !issues.empty()) {
            std::fprintf(stderr, "shopfloor: %s: %s\n", issues.front().key.c_str(),
                         issues.front().message.c_str());
            return kInvalidJob;
        }
        module = &machineFor(job);
        plan = module->plan(job, readTextFile(o.run));
        if (!plan.ok()) {
            std::fprintf(stderr, "shopfloor: %s\n", plan.outcome.message.c_str());
            return kUnreachable;
        }
    }

    SafeShutdown::install(); // Ctrl-C / SIGTERM end the loop below (the run stops safely first)
    HeadlessCell cell;
    shopfloor::MosquittoLinkOptions options;
    options.log = [](const std::string& line) {
        std::fprintf(stderr, "shopfloor: %s\n", line.c_str());
    };
    shopfloor::MosquittoLink link(config, &cell, options);
    std::string error;
    if (!link.start(&error)) {
        std::fprintf(stderr, "shopfloor: %s\n", error.c_str());
        return kFailure;
    }

    shopfloor::CellSnapshot snap;
    if (module) snap = shopfloor::cellSnapshotOf(job, *module);
    snap.state = "Idle";
    const auto publish = [&] {
        snap.queue_length = cell.queueLength();
        link.submit(snap);
    };
    publish();

    int code = kOk;
    if (module) {
        EngineRunSetup setup;
        setup.command = "shopfloor";
        setup.realtime = o.realtime;
        setup.quiet = o.quiet;
        auto last = SteadyClock::now() - std::chrono::seconds(1);
        setup.on_telemetry = [&](MotionEngine& engine, const TelemetrySample& t) {
            if (cell.takeHold()) engine.feedHold(); // a remote feed hold is always allowed
            // The node rate-limits the axes itself; 50 ms here keeps the hand-over cheap.
            const auto now = SteadyClock::now();
            if (now - last < std::chrono::milliseconds(50)) return;
            last = now;
            shopfloor::applyTelemetry(snap, t);
            publish();
        };
        const EngineRunResult r = runOnEngine(job, *module, plan, setup);
        code = r.code;
        snap.state = code == kOk ? "Completed" : "Stopped";
        snap.progress = code == kOk ? 1.0 : snap.progress;
        if (code == kOk) {
            const json::Value* sim = r.report.find("simulated_s");
            snap.last_run = shopfloor::lastRunFiguresOf(
                r.report, sim && sim->isNumber() ? sim->asNumber() : 0.0, "completed");
            std::printf("%s\n", json::write(r.report).c_str());
        }
        publish();
    }
    // Linger: stay connected for --linger-s (the last values and the queue reach the broker);
    // without --run until a signal.
    const auto until =
        SteadyClock::now() + std::chrono::milliseconds(static_cast<long>(o.linger_s * 1000.0));
    while (!SafeShutdown::requestedSignal() &&
           ((!module && o.linger_s <= 0) || SteadyClock::now() < until)) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        publish();
    }
    const shopfloor::LinkStatus status = link.status();
    link.stop();
    std::fprintf(stderr, "shopfloor: link %s; %u job(s) left in the queue\n", status.text.c_str(),
                 cell.queueLength());
    return code;
}

} // namespace cutcell::cli
