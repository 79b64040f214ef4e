#include "can_rig.h"

#include "can_link.h"
#include "can_panel_feed.h"
#include "production_record.h"

#include "core/machine/machine_registry.h"
#include "devices/canopen/cell_safe_stop.h"
#include "devices/machines/can_cells.h"
#include "devices/machines/sim_rig_registry.h"
#include "devices/process/safe_shutdown.h"
#include "devices/sim/simulated_torch.h"
#include "ui/machine/machine_ui_registry.h"

#include <atomic>
#include <cstdio>
#include <stdexcept>

namespace cutcell::app {
namespace {

using namespace cutcell::canopen;

// The rig exists with the bus down: the engine runs (drives read "disabled"), and the bus is
// brought up by the link worker when the operator asks (Enable, Reconnect), never here.
class CanRig : public CutCell::ui::EngineRig {
  public:
    explicit CanRig(const Job& job) : period_(job.sim.period_s) {
        // The machine's cell - which node is which axis (mode, scaling) or encoder - from the
        // same table the CLI builds its cell from (devices/machines/can_cells.cpp).
        const MachineModule& module = machineFor(job);
        if (const Outcome can = module.canOpen(); !can.ok()) throw std::runtime_error(can.message);
        const MachinePlan plan = module.plan(job);
        const MotionProgram* program = plan.ok() && plan.program ? plan.program.get() : nullptr;
        CanCellConfig cell;
        if (std::string why; !makeCanCell(job, period_, program, &cell, &why))
            throw std::runtime_error(why);
        config_ = cell.master;
        config_.sync = SyncSource::LastDriveWrite;
        cellText_ = cell.description;
        if (program) toolName_ = program->terms.tool;
        // The device panel names each node's axis (or sensor) as the machine does.
        if (const auto* machine = CutCell::ui::machineUiFor(job))
            for (const auto& axis : machine->axes())
                axisNames_.push_back(axis.name);
        axisNames_.resize(static_cast<size_t>(cell.axis_count));
        for (const std::string& sensor : module.sensorNames())
            axisNames_.push_back(QString::fromStdString(sensor));
        master_ = std::make_unique<CanOpenMaster>(config_);
        // Refused at once, without touching the bus: bus load, plugin, interface.
        if (std::string why; !master_->checkConfig(&why)) throw std::runtime_error(why);
        // The master's events (node configured, heartbeat lost, EMCY) into the run log too.
        master_->setEventSink([this](const MasterEvent& e) {
            if (MotionEngine* engine = engineForEvents_.load(std::memory_order_acquire))
                engine->logExternalEvent(e.error ? Severity::Warning : Severity::Info, e.text);
        });
        EngineDevices devices;
        for (int i = 0; i < cell.axis_count; ++i)
            devices.axes[static_cast<size_t>(i)] = master_->drive(i);
        for (int k = 0; k < cell.sensor_count && k < kMaxSensors; ++k)
            devices.sensors[static_cast<size_t>(k)] = master_->encoder(k);
        devices.torch = &torch_;
        EngineConfig config;
        config.period_s = period_;
        config.spec = job.engine;
        // The machine's own engine settings (windows, margins), then the bus's on top, as
        // `cutcell-cli run --devices canopen` does.
        if (program)
            if (std::string noRig; const auto machineRig = makeSimulatedRig(job, *program, &noRig))
                machineRig->configure(config);
        config.clock = ClockMode::RealTime; // the bus runs on the wall clock
        tuneEngineForCanCell(config, cell, job, period_);
        engine_ = std::make_unique<MotionEngine>(devices, config);
        engine_->setRunRecord(productionRecord());
        engine_->startThread();
        engineForEvents_.store(engine_.get(), std::memory_order_release);
        link_ = std::make_unique<CanLink>(*master_, where());
        link_->setFinalAction(
            [this](bool masterRunning) { safeStop("the window was closed", masterRunning); });
        safeStopRegistration_ = SafeShutdown::add([this](const std::string& why) {
            const auto s = link_->status().state;
            using L = CutCell::ui::RigLink::State;
            safeStop(why, s == L::Up || s == L::Connecting || s == L::Lost);
        });
    }
    ~CanRig() override {
        engine_->emergencyStop(); // torch off now, from this thread
        safeStopRegistration_.reset();
        link_.reset(); // on the worker: the safe stop (drives disabled, logged), master stopped
        engineForEvents_.store(nullptr, std::memory_order_release);
        engine_->stopThread();
    }
    // Any ending of the program (signal, std::terminate, closing the window): once.
    void safeStop(const std::string& why, bool masterRunning) {
        if (safeStopped_.exchange(true)) return;
        safeStopCanCell(engine_.get(), masterRunning ? master_.get() : nullptr, why, "cutcell",
                        toolName_);
    }

    MotionEngine& engine() override { return *engine_; }
    std::string description() const override {
        // One template, so that the GUI can translate the line (tools/core_messages.py).
        char buf[320];
        std::snprintf(
            buf, sizeof buf,
            "CANopen cell: %s on %s at %d kbit/s + simulated tool, %.3g ms SYNC, real time",
            cellText_.c_str(), where().c_str(), config_.bitrate_bps / 1000, period_ * 1000.0);
        return buf;
    }
    bool deviceSnapshot(ui::DevicePanelSnapshot& out) override {
        const CutCell::ui::RigLink link = link_->status();
        out = toPanelSnapshot(master_->snapshot(), axisNames_, &link,
                              config_.heartbeat_timeout_s * 1e3);
        return true;
    }
    // Drive faults are reset by the engine's reset; the bus by reconnectLink() (RunController).
    void faultReset(int /*node*/) override {}

    CutCell::ui::RigLink link() const override { return link_->status(); }
    void connectLink() override { link_->requestUp(); }
    void reconnectLink() override { link_->requestReconnect(); }
    std::vector<CutCell::ui::RigLinkEvent> drainLinkEvents() override {
        std::vector<CutCell::ui::RigLinkEvent> out;
        for (const MasterEvent& e : master_->drainEvents())
            out.push_back({e.error, e.text});
        return out;
    }

  private:
    std::string where() const {
        return config_.plugin.toStdString() + " " + config_.interface.toStdString();
    }

    double period_;
    CanOpenMasterConfig config_;
    std::string cellText_; // "4 CiA 402 drives (CSP) + CiA 406 encoder 5 (line encoder)"
    std::vector<QString> axisNames_;
    std::unique_ptr<CanOpenMaster> master_;
    SimulatedTorch torch_;
    std::unique_ptr<MotionEngine> engine_; // destroyed before the devices
    std::atomic<MotionEngine*> engineForEvents_{nullptr};
    std::unique_ptr<CanLink> link_; // destroyed first: it stops the master
    std::atomic<bool> safeStopped_{false};
    std::string toolName_ = "tool"; // the program's (torch, saw, cutter), for the safe stop's line
    SafeShutdown::Registration safeStopRegistration_;
};

} // namespace

std::unique_ptr<CutCell::ui::EngineRig> makeCanRig(const Job& job, std::string* error) {
    std::string ignored;
    if (!error) error = &ignored;
    try {
        return std::make_unique<CanRig>(job);
    } catch (const std::exception& e) {
        *error = e.what();
        return nullptr;
    }
}

} // namespace cutcell::app
