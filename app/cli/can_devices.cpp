#include "can_devices.h"

#include "devices/canopen/canopen_master.h"
#include "devices/canopen/cell_safe_stop.h"
#include "devices/canopen/drive_simulator.h"
#include "devices/canopen/engine_tuning.h"
#include "devices/machines/can_cells.h"

#include "qt_app.h"

#include <chrono>
#include <cstdio>
#include <thread>

namespace cutcell::cli {

using namespace cutcell::canopen;

CanEngineDevices::CanEngineDevices() = default;

CanEngineDevices::~CanEngineDevices() {
    if (master_) master_->stop();
    master_.reset();
    sim_.reset();
}

bool CanEngineDevices::start(const Job& job, const CanRunOptions& o, const MotionProgram* program,
                             std::string* error) {
    if (!app_) app_ = ensureQCoreApplication();
    period_ = o.period_s > 0 ? o.period_s : job.sim.period_s;
    CanCellConfig cell;
    if (!makeCanCell(job, period_, program, &cell, error)) return false;
    axisCount_ = cell.axis_count;
    sensorCount_ = cell.sensor_count;
    description_ = cell.description;
    if (program) toolName_ = program->terms.tool;
    homeSpeedDegS_ = job.engine.home_speed_deg_s;
    CanOpenMasterConfig& mc = cell.master;
    if (!o.plugin.empty()) mc.plugin = QString::fromStdString(o.plugin);
    if (!o.interface.empty()) mc.interface = QString::fromStdString(o.interface);
    mc.sync = SyncSource::LastDriveWrite;
    masterConfig_ = mc;
    fastestLinear_ = cell.fastest_linear_mm_s;
    if (o.in_process_simulator) {
        DriveSimulatorConfig sc;
        sc.plugin = mc.plugin;
        sc.interface = mc.interface;
        sc.nodes = cell.sim_drives;
        sc.encoders = cell.sim_encoders;
        sim_ = std::make_unique<DriveSimulator>(sc);
        if (!sim_->start()) {
            *error = "drive simulator: " + sim_->errorText().toStdString();
            return false;
        }
    }
    master_ = std::make_unique<CanOpenMaster>(mc);
    master_->setEventSink([this](const MasterEvent& e) {
        if (e.error) std::fprintf(stderr, "%s\n", e.text.c_str());
        std::lock_guard lock(engineMutex_);
        if (engine_) engine_->logExternalEvent(e.error ? Severity::Error : Severity::Info, e.text);
    });
    if (!master_->start(error)) return false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (!master_->allOperational()) {
        // A node that failed its bring-up (an SDO abort, the wrong device, no boot-up) ends it
        // at once: waiting out the deadline would not change the answer.
        std::string failed;
        for (const CanNodeSnapshot& n : master_->snapshot().nodes)
            if (!n.configured && !n.fault_text.empty())
                failed += "; node " + std::to_string(n.node) + ": " + n.fault_text;
        if (!failed.empty()) {
            *error = "the CAN nodes' bring-up failed" + failed;
            return false;
        }
        if (std::chrono::steady_clock::now() > deadline) {
            *error = "not every CAN node became operational within 5 s";
            for (const CanNodeSnapshot& n : master_->snapshot().nodes)
                if (!n.configured)
                    *error += "; node " + std::to_string(n.node) + ": " +
                              (n.fault_text.empty() ? "no answer" : n.fault_text);
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return true;
}

void CanEngineDevices::attachEngine(MotionEngine* engine) {
    std::lock_guard lock(engineMutex_);
    engine_ = engine;
}

void CanEngineDevices::safeStop(const std::string& why) {
    if (safeStopped_.exchange(true)) return;
    MotionEngine* engine;
    {
        std::lock_guard lock(engineMutex_);
        engine = engine_;
    }
    safeStopCanCell(engine, master_.get(), why, "cutcell-cli", toolName_);
}

bool CanEngineDevices::awaitAnswers(std::uint64_t sentBefore, std::string* error) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
    for (;;) {
        const std::uint64_t sent = master_->cyclesSent();
        if (sent > sentBefore && master_->cyclesCompleted() >= sent) return true;
        if (std::chrono::steady_clock::now() > deadline) break;
        std::this_thread::sleep_for(std::chrono::microseconds(20));
    }
    const std::uint64_t sent = master_->cyclesSent();
    *error =
        sent > sentBefore
            ? "no process data (TPDO) from every node within 500 ms of SYNC " + std::to_string(sent)
            : std::string("no SYNC went out within 500 ms of the engine's cycle");
    for (const CanNodeSnapshot& n : master_->snapshot().nodes)
        if (!n.fault_text.empty())
            *error += "; node " + std::to_string(n.node) + ": " + n.fault_text;
    return false;
}

AxisDrive* CanEngineDevices::axis(int i) {
    return master_ && i < master_->driveCount() ? master_->drive(i) : nullptr;
}

SensorInput* CanEngineDevices::sensor(int k) {
    return master_ && k < master_->encoderCount() ? master_->encoder(k) : nullptr;
}

void CanEngineDevices::tune(EngineConfig& config, const Job& job) const {
    CanCellConfig cell;
    cell.master = masterConfig_;
    cell.fastest_linear_mm_s = fastestLinear_;
    tuneEngineForCanCell(config, cell, job, period_);
}

} // namespace cutcell::cli
