#pragma once
// The CANopen drives of a job (devices section, or the CLI's overrides) for the motion engine:
// the master on its own thread with SYNC posted by the engine's last write each cycle, and an
// optional in-process drive simulator (a real peer on the bus, on its own thread).
#include "can_run.h"
#include "core/devices/device_interfaces.h"
#include "core/engine/motion_engine.h"
#include "core/job/job.h"
#include "devices/canopen/canopen_master.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <string>

class QCoreApplication;

namespace cutcell::canopen {
class CanOpenMaster;
class DriveSimulator;
} // namespace cutcell::canopen

namespace cutcell::cli {

class CanEngineDevices {
  public:
    CanEngineDevices();
    ~CanEngineDevices();

    // The machine's cell (devices/machines/can_cells.h: a CiA 402 drive per axis, a CiA 406
    // encoder per sensor). Checks the bus load, connects, configures every node and waits (5 s
    // at most) until all are operational. False with the reason (figures, node and cause)
    // otherwise. program (may be null): where the simulated axes start.
    bool start(const Job& job, const CanRunOptions& options, const MotionProgram* program,
               std::string* error);
    double period() const { return period_; }
    int axisCount() const { return axisCount_; }
    int sensorCount() const { return sensorCount_; }
    AxisDrive* axis(int i);
    SensorInput* sensor(int k);
    const std::string& description() const { return description_; }
    // Engine settings that depend on the drives: in-position windows from the encoder
    // resolution (the engine's defaults suit exact simulated drives).
    void tune(EngineConfig& config, const Job& job) const; // see canopen/engine_tuning.h
    canopen::CanOpenMaster& master() { return *master_; }
    // Lock-step: waits (500 ms at most) until the SYNC after `sentBefore` SYNCs went out and
    // every node answered it. False with what is missing (the nodes and their faults).
    bool awaitAnswers(std::uint64_t sentBefore, std::string* error);
    // The master's events (faults with node and decoded reason: "node 3: EMCY 0x2310
    // over-current", "node 2: heartbeat lost ...", "CAN bus: connection to the bus lost")
    // go into this engine's run log (events.log) as they happen, and errors to stderr. Null
    // detaches (before the engine goes).
    void attachEngine(MotionEngine* engine);
    // Brings the cell to a safe state (engine emergency stop: torch off; then every drive
    // disabled on the bus) and logs why, once. From a signal's watcher, std::terminate or the
    // program's way out.
    void safeStop(const std::string& why);

  private:
    std::mutex engineMutex_; // guards engine_ against the master thread's event sink
    MotionEngine* engine_ = nullptr;
    std::atomic<bool> safeStopped_{false};
    std::string toolName_ = "tool"; // the program's (torch, saw, cutter), for the safe stop's line
    std::unique_ptr<QCoreApplication> app_;
    std::unique_ptr<canopen::DriveSimulator> sim_;
    std::unique_ptr<canopen::CanOpenMaster> master_;
    double period_ = 0;
    int axisCount_ = 0, sensorCount_ = 0;
    std::string description_;
    canopen::CanOpenMasterConfig masterConfig_;
    double fastestLinear_ = 0;
    double homeSpeedDegS_ = 20;
};

} // namespace cutcell::cli
