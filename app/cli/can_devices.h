#pragma once
// The CANopen drives of a job (devices section, or the CLI's overrides) for the motion engine:
// the master on its own thread with SYNC posted by the engine's last write each cycle, and an
// optional in-process drive simulator (a real peer on the bus, on its own thread).
#include "can_run.h"
#include "core/devices/device_interfaces.h"
#include "core/engine/motion_engine.h"
#include "core/job/job.h"

#include <memory>
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

    // Checks the bus load, connects, configures every node and waits (5 s at most) until all
    // are operational. False with the reason (figures, node and cause) otherwise.
    bool start(const Job& job, const CanRunOptions& options, std::string* error);
    double period() const { return period_; }
    AxisDrive* axis(int i);
    // Engine settings that depend on the drives: in-position windows from the encoder
    // resolution (the engine's defaults suit exact simulated drives).
    void tune(EngineConfig& config, const Job& job) const; // see canopen/engine_tuning.h
    canopen::CanOpenMaster& master() { return *master_; }

  private:
    std::unique_ptr<QCoreApplication> app_;
    std::unique_ptr<canopen::DriveSimulator> sim_;
    std::unique_ptr<canopen::CanOpenMaster> master_;
    double period_ = 0;
};

} // namespace cutcell::cli
