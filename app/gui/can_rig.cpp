#include "can_rig.h"

#include "can_panel_feed.h"

#include "devices/canopen/cell_safe_stop.h"
#include "devices/canopen/engine_tuning.h"
#include "devices/process/safe_shutdown.h"
#include "devices/sim/simulated_torch.h"
#include "ui/machine/machine_ui_registry.h"

#include <QCoreApplication>
#include <QDeadlineTimer>

#include <atomic>
#include <cstdio>

namespace cutcell::app {
namespace {

using namespace cutcell::canopen;

class CanRig : public CutCell::ui::EngineRig {
  public:
    explicit CanRig(const Job& job)
        : period_(job.sim.period_s), config_(masterConfigFromJob(job, period_, kAxisCount)) {
        config_.sync = SyncSource::LastDriveWrite;
        // The device panel names each node's axis as the machine does.
        if (const auto* machine = CutCell::ui::machineUiFor(job))
            for (const auto& axis : machine->axes())
                axisNames_.push_back(axis.name);
    }
    ~CanRig() override {
        safeStop("the window was closed"); // torch off, drives disabled on the bus, logged
        safeStopRegistration_.reset();
        if (engine_) engine_->stopThread();
        if (master_) master_->stop();
    }
    // Any ending of the program (signal, std::terminate, closing the window): once.
    void safeStop(const std::string& why) {
        if (!engine_ || safeStopped_.exchange(true)) return;
        safeStopCanCell(engine_.get(), master_.get(), why, "cutcell");
    }

    // Connects and configures every node; the wait is bounded (5 s) and keeps this thread's
    // event loop running (it may host the virtualcan bus).
    bool start(const Job& job, std::string* error) {
        master_ = std::make_unique<CanOpenMaster>(config_);
        if (!master_->start(error)) return false;
        QDeadlineTimer deadline(5000);
        while (!master_->allOperational()) {
            if (deadline.hasExpired()) {
                *error = "not every CAN node became operational within 5 s";
                for (const CanNodeSnapshot& n : master_->snapshot().nodes)
                    if (!n.configured)
                        *error += "; node " + std::to_string(n.node) + ": " +
                                  (n.fault_text.empty() ? "no answer" : n.fault_text);
                return false;
            }
            QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents, 5);
        }
        EngineDevices devices;
        for (int i = 0; i < kAxisCount; ++i)
            devices.axes[static_cast<size_t>(i)] = master_->drive(i);
        devices.torch = &torch_;
        EngineConfig config;
        config.clock = ClockMode::RealTime; // the bus runs on the wall clock
        config.spec = job.engine;
        config.gains = job.controller;
        tuneEngineForCan(config, job, period_);
        engine_ = std::make_unique<MotionEngine>(devices, config);
        engine_->startThread();
        safeStopRegistration_ =
            SafeShutdown::add([this](const std::string& why) { safeStop(why); });
        return true;
    }

    MotionEngine& engine() override { return *engine_; }
    std::string description() const override {
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "CANopen cell: 6 drives on %s %s at %d kbit/s + simulated torch, %.3g ms "
                      "SYNC, real time",
                      config_.plugin.toUtf8().constData(), config_.interface.toUtf8().constData(),
                      config_.bitrate_bps / 1000, period_ * 1000.0);
        return buf;
    }
    bool deviceSnapshot(ui::DevicePanelSnapshot& out) override {
        out = toPanelSnapshot(master_->snapshot(), axisNames_);
        return true;
    }
    void faultReset(int /*node*/) override {
        // A bus fault needs a reconnection; drive faults are reset by the engine's reset.
        const BusState bus = master_->snapshot().bus;
        if (bus == BusState::BusOff || bus == BusState::Disconnected) master_->recoverBus();
    }

  private:
    double period_;
    CanOpenMasterConfig config_;
    std::vector<QString> axisNames_;
    std::unique_ptr<CanOpenMaster> master_;
    SimulatedTorch torch_;
    std::unique_ptr<MotionEngine> engine_; // declared last: destroyed before the devices
    std::atomic<bool> safeStopped_{false};
    SafeShutdown::Registration safeStopRegistration_;
};

} // namespace

std::unique_ptr<CutCell::ui::EngineRig> makeCanRig(const Job& job, std::string* error) {
    std::string ignored;
    if (!error) error = &ignored;
    try {
        auto rig = std::make_unique<CanRig>(job);
        if (!rig->start(job, error)) return nullptr;
        return rig;
    } catch (const std::exception& e) {
        *error = e.what();
        return nullptr;
    }
}

} // namespace cutcell::app
