#include "bench_can.h"

#include "core/job/default_job.h"
#include "core/machine/machine_registry.h"
#include "devices/canopen/bus_load.h"
#include "devices/canopen/canopen_master.h"
#include "devices/canopen/drive_simulator.h"
#include "devices/canopen/pdo.h"
#include "devices/canopen/qt_can_frame.h"
#include "devices/machines/can_cells.h"
#include "devices/net/loopback_port.h"

#include "qt_app.h"
#include <QCanBus>
#include <QCanBusDevice>
#include <QThread>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <thread>
#include <unistd.h>

namespace cutcell::cli {
namespace {

using namespace cutcell::canopen;
using Clock = std::chrono::steady_clock;

std::int64_t nowNs() {
    return Clock::now().time_since_epoch().count();
}

// An independent bus client on its own thread that time-stamps the urgent stop frames (RPDO2).
class StopFrameProbe {
  public:
    bool start(const QString& interface) {
        thread_.start();
        context_.moveToThread(&thread_);
        bool ok = false;
        QMetaObject::invokeMethod(
            &context_,
            [&] {
                device_ = QCanBus::instance()->createDevice("virtualcan", interface);
                if (!device_) return;
                QObject::connect(device_, &QCanBusDevice::framesReceived, &context_, [this] {
                    const std::int64_t t = nowNs();
                    while (device_->framesAvailable()) {
                        CanFrame f;
                        std::uint16_t cw = 0;
                        if (fromQt(device_->readFrame(), f) && decodeRpdo2(f, cw)) {
                            std::lock_guard lock(mutex_);
                            stops_.push_back(t);
                        }
                    }
                });
                ok = device_->connectDevice();
            },
            Qt::BlockingQueuedConnection);
        const auto deadline = Clock::now() + std::chrono::seconds(3);
        while (ok && Clock::now() < deadline) {
            bool connected = false;
            QMetaObject::invokeMethod(
                &context_, [&] { connected = device_->state() == QCanBusDevice::ConnectedState; },
                Qt::BlockingQueuedConnection);
            if (connected) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return false;
    }
    ~StopFrameProbe() {
        QMetaObject::invokeMethod(
            &context_, [&] { delete device_; }, Qt::BlockingQueuedConnection);
        thread_.quit();
        thread_.wait();
    }
    void clear() {
        std::lock_guard lock(mutex_);
        stops_.clear();
    }
    std::vector<std::int64_t> stops() {
        std::lock_guard lock(mutex_);
        return stops_;
    }

  private:
    QThread thread_;
    QObject context_;
    QCanBusDevice* device_ = nullptr;
    std::mutex mutex_;
    std::vector<std::int64_t> stops_;
};

// The engine's part while holding still: read every drive, write its actual position.
bool holdAll(CanOpenMaster& m, DriveState want) {
    bool all = true;
    for (int i = 0; i < m.driveCount(); ++i) {
        const DriveFeedback fb = m.drive(i)->read(0);
        m.drive(i)->write(fb.position);
        all = all && fb.state == want;
    }
    return all;
}

// lockStep: this thread produces the SYNCs (SyncSource::External).
bool waitFor(CanOpenMaster& m, DriveState want, double seconds, bool lockStep = false) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < deadline) {
        if (holdAll(m, want)) return true;
        if (lockStep) m.sync();
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
}

bool bringUp(CanOpenMaster& m, std::string& error, bool lockStep = false) {
    if (!m.start(&error)) return false;
    const auto deadline = Clock::now() + std::chrono::seconds(5);
    while (!m.allOperational()) {
        if (Clock::now() > deadline) {
            error = "nodes not operational within 5 s";
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    for (int i = 0; i < m.driveCount(); ++i)
        m.drive(i)->activate();
    if (!waitFor(m, DriveState::Enabled, 3, lockStep)) {
        error = "drives not enabled within 3 s";
        return false;
    }
    return true;
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<size_t>(p * static_cast<double>(v.size())))];
}

} // namespace

void benchCan(json::Object& out, bool quick) {
    const auto app = ensureQCoreApplication();

    Job job = defaultJob();
    const QString interface =
        QStringLiteral("tcp://127.0.0.1:%1/can0").arg(net::freeLoopbackPort());
    job.devices.can_interface = interface.toStdString();
    // The shortest cycle the bus admits for the default job's drives, rounded up to 0.5 ms.
    BusLoadInput in;
    in.nodes = static_cast<int>(machineFor(job).axes(job).size());
    in.bitrate_bps = job.devices.bitrate_bps;
    in.heartbeat_period_s = job.devices.heartbeat_timeout_ms * 1e-3 / 3;
    const double period = std::ceil(computeBusLoad(in).min_period_s * 2000) / 2000;

    CanCellConfig cell; // the default job's machine on CAN: its master's and simulator's nodes
    if (std::string why; !makeCanCell(job, period, nullptr, &cell, &why)) {
        std::fprintf(stderr, "bench: no CAN cell: %s\n", why.c_str());
        return;
    }

    StopFrameProbe probe; // first client: hosts the private bus on its thread
    if (!probe.start(interface)) {
        std::fprintf(stderr, "bench: CAN listener could not connect to %s\n",
                     qPrintable(interface));
        return;
    }
    DriveSimulatorConfig sc;
    sc.interface = interface;
    sc.nodes = cell.sim_drives;
    sc.encoders = cell.sim_encoders;
    DriveSimulator sim(sc);
    if (!sim.start()) {
        std::fprintf(stderr, "bench: drive simulator: %s\n", qPrintable(sim.errorText()));
        return;
    }
    out.emplace_back("can_period_ms", period * 1e3);

    std::string error;
    {
        // SYNC from the pacing thread; the jitter is measured where the SYNC is written.
        CanOpenMaster m(cell.master);
        if (!bringUp(m, error)) {
            std::fprintf(stderr, "bench: CAN master: %s\n", error.c_str());
            return;
        }
        m.resetJitter();
        const auto until = Clock::now() + std::chrono::milliseconds(quick ? 1000 : 3000);
        while (Clock::now() < until) {
            holdAll(m, DriveState::Enabled);
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        const MasterStats s = m.stats();
        out.emplace_back("can_cycle_jitter_us_p50", s.sync_jitter_us_p50);
        out.emplace_back("can_cycle_jitter_us_p99", s.sync_jitter_us_p99);
        out.emplace_back("can_cycle_jitter_us_max", s.sync_jitter_us_max);

        // Emergency stop: quickStop() on every drive (the engine's stop path) -> last stop
        // frame on the bus, heard by the independent listener. Many stops per enable run (the
        // master sends the stop frames whatever the drives' state), so >= 1000 trials take
        // seconds and the p99 is a p99, not the maximum.
        std::vector<double> latencies;
        const int runs = quick ? 2 : 5;
        const int stopsPerRun = quick ? 100 : 200;
        std::uint64_t jitterSeed = 12345;
        for (int run = 0; run < runs; ++run) {
            for (int k = 0; k < stopsPerRun; ++k) {
                probe.clear();
                const std::int64_t t0 = nowNs();
                for (int i = 0; i < m.driveCount(); ++i)
                    m.drive(i)->quickStop();
                const auto deadline = Clock::now() + std::chrono::seconds(1);
                std::vector<std::int64_t> heard;
                while ((heard = probe.stops()).size() < static_cast<size_t>(m.driveCount()) &&
                       Clock::now() < deadline)
                    std::this_thread::sleep_for(std::chrono::microseconds(20));
                if (heard.size() < static_cast<size_t>(m.driveCount())) {
                    std::fprintf(stderr, "bench: only %zu of %d stop frames heard\n", heard.size(),
                                 m.driveCount());
                    break;
                }
                latencies.push_back(
                    static_cast<double>(heard[static_cast<size_t>(m.driveCount()) - 1] - t0) *
                    1e-3);
                // 0.3 .. 1.3 ms apart: the stops fall at every phase of the SYNC cycle.
                jitterSeed = jitterSeed * 6364136223846793005ULL + 1442695040888963407ULL;
                std::this_thread::sleep_for(
                    std::chrono::microseconds(300 + static_cast<int>((jitterSeed >> 33) % 1000)));
            }
            if (!waitFor(m, DriveState::Disabled, 2)) break;
            for (int i = 0; i < m.driveCount(); ++i)
                m.drive(i)->activate();
            if (!waitFor(m, DriveState::Enabled, 2)) break;
        }
        out.emplace_back("can_estop_latency_us_p50", percentile(latencies, 0.5));
        out.emplace_back("can_estop_latency_us_p99", percentile(latencies, 0.99));
        out.emplace_back("can_estop_latency_us_max", percentile(latencies, 1.0));
        out.emplace_back("can_estop_runs", runs);
        out.emplace_back("can_estop_trials", static_cast<int>(latencies.size()));
        m.stop();
    }
    {
        // Sustained frames: lock-step cycles (write, SYNC, wait for all TPDOs) back to back.
        CanOpenMasterConfig c = cell.master;
        c.sync = SyncSource::External;
        CanOpenMaster m(c);
        if (!bringUp(m, error, true)) {
            std::fprintf(stderr, "bench: CAN master (lock-step): %s\n", error.c_str());
            return;
        }
        const MasterStats before = m.stats();
        std::uint64_t expected = m.cyclesSent();
        const auto t0 = Clock::now();
        const auto until = t0 + std::chrono::milliseconds(quick ? 1000 : 3000);
        while (Clock::now() < until) {
            holdAll(m, DriveState::Enabled);
            ++expected;
            m.sync();
            const auto deadline = Clock::now() + std::chrono::milliseconds(500);
            while (m.cyclesCompleted() < expected && Clock::now() < deadline)
                std::this_thread::yield();
        }
        const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
        const MasterStats after = m.stats();
        out.emplace_back("can_frames_per_s",
                         static_cast<double>(after.frames_tx - before.frames_tx + after.frames_rx -
                                             before.frames_rx) /
                             wall);
        out.emplace_back("can_lockstep_cycles_per_s",
                         static_cast<double>(after.cycles - before.cycles) / wall);
        m.stop();
    }
}

} // namespace cutcell::cli
