#pragma once
// Each machine's cell on a CANopen bus, from its job: what the master configures - one CiA 402
// drive per axis of the machine (MachineModule::axes(): its unit, and CSP or CST by its
// command mode; node id and scaling from devices.node_ids / counts_per_unit) and one CiA 406
// encoder per sensor the machine reads (MachineModule::sensorNames(); devices.sensor_node_ids)
// - and what the drive simulator plays behind those nodes: each drive's controller and
// mechanics, each encoder's measured quantity (the flying saw's pipe line with its speed
// profile seen by the measuring roller, the quick-return slider seen by its scale).
//
// The drives and encoders themselves are generic (devices/canopen); each machine's own part of
// its cell lives in its folder (devices/machines/<name>/<name>_can_cell.cpp, can_cell_machine.h)
// and is listed once in can_cell_registry.cpp, as sim_rig_registry does for the simulated cells.
// A machine without an entry is refused by name, never built as another machine's cell.
#include "core/engine/motion_engine.h"
#include "core/engine/motion_program.h"
#include "core/job/job.h"
#include "core/json/json.h"
#include "devices/canopen/canopen_master.h"
#include "devices/canopen/drive_simulator.h"

#include <memory>
#include <string>
#include <vector>

namespace cutcell {

struct CanCellConfig {
    canopen::CanOpenMasterConfig master; // nodes: the axes in order, then the encoders
    std::vector<canopen::DriveNodeConfig> sim_drives;
    std::vector<canopen::EncoderNodeConfig> sim_encoders;
    int axis_count = 0;
    int sensor_count = 0;
    // The fastest linear axis's speed limit (mm/s; 0: none faster than homing): the engine's
    // frozen-feedback margin over a bus must cover it (engine_tuning.h).
    double fastest_linear_mm_s = 0;
    std::string description; // "4 CiA 402 drives (CSP) + 1 CiA 406 encoder (line encoder)"
};

// The cell of job.machine with period_s as the SYNC period. program (may be null): the
// simulated axes start at its reference, as the simulated rigs do. False + *error for a machine
// without CAN drives or a job the cell cannot be built from.
// The engine's settings for the cell (period, set-point lead, windows, frozen-feedback margin
// for the bus's delay) on top of the machine's own (its simulated rig's configure()).
void tuneEngineForCanCell(EngineConfig& config, const CanCellConfig& cell, const Job& job,
                          double period_s);

bool makeCanCell(const Job& job, double period_s, const MotionProgram* program, CanCellConfig* out,
                 std::string* error);

// The simulated drives of job.machine's CAN cell (at the job's sim.period_s) with these node ids,
// in the order given (a drive simulator playing part of the cell: tests, `cutcell-cli drivesim
// --nodes`). Throws std::invalid_argument naming the node and the cell's drives for an id that
// is not one of them, or why the machine has no CAN cell.
std::vector<canopen::DriveNodeConfig> canCellDriveNodes(const Job& job,
                                                        const std::vector<int>& ids);

// What a machine measures on its CAN cell besides the engine's figures - the flying saw: the
// cut length of every piece, as its simulated rig reports it - from the engine's devices,
// between which and the engine it sits. Built per run; lives as long as the engine.
class CanCellMeter {
  public:
    virtual ~CanCellMeter() = default;
    // Before the engine is built from `devices`: puts the meter in between (engine thread).
    virtual void attach(EngineDevices& devices) = 0;
    virtual void addToReport(json::Value& doc) const = 0; // after the run
    virtual std::string summary(const std::string& outcome) const = 0;
};

// The meter of job.machine's CAN cell; nullptr when it measures nothing more.
std::unique_ptr<CanCellMeter> makeCanCellMeter(const Job& job, const MotionProgram& program);
// One per machine that has one (its own file in this folder).
std::unique_ptr<CanCellMeter> makeFlyingSawCanMeter(const Job& job, const MotionProgram& program);

} // namespace cutcell
