#pragma once
// What one machine adds to its CAN cell (devices/machines/can_cells.h): the drive simulator's
// side of its nodes - each drive's controller and mechanics, each encoder's measured quantity -
// and the fastest linear axis. The master's side (one CiA 402 node per axis in the axis's mode
// and unit, one CiA 406 node per sensor) is common and already filled in. Each machine has one
// such function in its own folder, listed once in can_cell_registry.cpp.
#include "core/engine/motion_program.h"
#include "core/job/job.h"
#include "devices/canopen/drive_simulator.h"
#include "devices/machines/can_cells.h"

#include <functional>
#include <string>

namespace cutcell {

class CanCellBuilder {
  public:
    CanCellBuilder(const Job& theJob, double period, const MotionProgram* theProgram,
                   CanCellConfig& theCell)
        : job(theJob), period_s(period), program(theProgram), cell(theCell) {}

    const Job& job;
    const double period_s;
    const MotionProgram* program; // may be null: the simulated axes start at 0
    CanCellConfig& cell;

    // Where the simulated axis starts: the program's reference (as the simulated rigs do).
    double startOf(int axis) const { return program ? program->reference[axis] : 0.0; }
    bool linear(int axis) const;
    // A simulated drive for axis `axis` with its node id and encoder scaling from the job.
    canopen::DriveNodeConfig driveNode(int axis, const PidGains& gains,
                                       const JointPlantParams& plant) const;
    // The simulated CiA 406 encoder of sensor k: counts per unit and what it measures (t: s).
    void addEncoder(int k, double countsPerUnit, std::function<double(double)> position);
};

// Fills the simulator's side of the machine's cell; false + *error when the job cannot give it.
using CanCellFill = bool (*)(CanCellBuilder& b, std::string* error);
// The meter of a machine's cell (may return null: nothing more measured).
using CanCellMeterFactory = std::unique_ptr<CanCellMeter> (*)(const Job&, const MotionProgram&);

// One per machine with CANopen drives (its own folder).
bool fillPipeRobotCanCell(CanCellBuilder& b, std::string* error);
bool fillSectionSteelCanCell(CanCellBuilder& b, std::string* error);
bool fillFlyingSawCanCell(CanCellBuilder& b, std::string* error);
bool fillQuickReturnCanCell(CanCellBuilder& b, std::string* error);

// The registry's entry of a machine id (null: no CAN cell for that machine).
struct CanCellEntry {
    const char* machine;
    CanCellFill fill;
    CanCellMeterFactory meter; // may be null
};
const CanCellEntry* findCanCell(const std::string& machineId);

} // namespace cutcell
