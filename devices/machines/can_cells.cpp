#include "devices/machines/can_cells.h"
#include "core/common/c_format.h"
#include "core/machine/counts_reach.h"

#include "core/machine/machine_registry.h"
#include "devices/canopen/engine_tuning.h"
#include "devices/machines/can_cell_machine.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace cutcell {

using namespace canopen;

bool CanCellBuilder::linear(int axis) const {
    return cell.master.nodes[static_cast<size_t>(axis)].linear;
}

DriveNodeConfig CanCellBuilder::driveNode(int axis, const PidGains& gains,
                                          const JointPlantParams& plant) const {
    DriveNodeConfig c;
    c.node = job.devices.node_ids[static_cast<size_t>(axis)];
    c.gains = gains;
    c.plant = plant;
    c.counts_per_rad =
        countsPerRad(job.devices.counts_per_unit[static_cast<size_t>(axis)], linear(axis));
    c.max_loop_period_s = std::min(0.001, period_s);
    return c;
}

void CanCellBuilder::addEncoder(int k, double countsPerUnit,
                                std::function<double(double)> position) {
    MasterNodeConfig n;
    n.node = sensorNodeId(job.devices, cell.axis_count, k);
    n.counts_per_unit = countsPerUnit;
    n.linear = true;
    n.encoder = true;
    cell.master.nodes.push_back(n);
    EncoderNodeConfig e;
    e.node = n.node;
    e.counts_per_unit = countsPerUnit;
    e.position = std::move(position);
    cell.sim_encoders.push_back(std::move(e));
}

bool makeCanCell(const Job& job, double period_s, const MotionProgram* program, CanCellConfig* out,
                 std::string* error) {
    const MachineModule& module = machineFor(job);
    if (const Outcome can = module.canOpen(); !can.ok()) {
        if (error) *error = can.message;
        return false;
    }
    const CanCellEntry* entry = findCanCell(module.id());
    if (!entry) {
        if (error)
            *error = "the machine \"" + module.id() +
                     "\" has no CAN cell (devices/machines/can_cell_registry.cpp)";
        return false;
    }
    // The master's side, the same for every machine: a CiA 402 node per axis in its mode and
    // unit; the machine adds the simulator's side and its encoders.
    const std::vector<AxisInfo> axes = module.axes(job);
    const std::vector<std::string> sensors = module.sensorNames();
    CanCellConfig c;
    c.axis_count = static_cast<int>(axes.size());
    c.sensor_count = static_cast<int>(sensors.size());
    c.master = masterConfigFromJob(job, period_s, 0);
    c.master.nodes.clear();
    int csp = 0, cst = 0;
    for (int a = 0; a < c.axis_count; ++a) {
        MasterNodeConfig n;
        n.node = job.devices.node_ids[static_cast<size_t>(a)];
        n.counts_per_unit = job.devices.counts_per_unit[static_cast<size_t>(a)];
        n.linear = axes[static_cast<size_t>(a)].unit == AxisUnit::Linear;
        n.mode = axes[static_cast<size_t>(a)].mode;
        (n.mode == AxisCommandMode::Torque ? cst : csp)++;
        c.master.nodes.push_back(n);
    }
    // A continuous axis's counts grow with the run: they must stay within a drive's 32 bits.
    if (program)
        if (const Outcome fits = countsFitProgram(job, *program); !fits.ok()) {
            if (error) *error = fits.message;
            return false;
        }
    CanCellBuilder builder(job, period_s, program, c);
    if (!entry->fill(builder, error)) return false;
    if (static_cast<int>(c.sim_encoders.size()) != c.sensor_count) {
        if (error)
            *error = "the CAN cell of \"" + module.id() + "\" has " +
                     std::to_string(c.sim_encoders.size()) + " encoders for " +
                     std::to_string(c.sensor_count) + " sensors";
        return false;
    }
    // Templates the GUI translates (tools/core_messages.py), one more for each encoder.
    c.description = cst == 0 ? messageC("%d CiA 402 drives (CSP)", csp)
                    : csp == 0
                        ? messageC("%d CiA 402 drives (CST)", cst)
                        : messageC("%d CiA 402 drives (%d CSP, %d CST)", csp + cst, csp, cst);
    for (int k = 0; k < c.sensor_count; ++k)
        c.description = messageC("%s + CiA 406 encoder %d (%s)", c.description.c_str(),
                                 sensorNodeId(job.devices, c.axis_count, k),
                                 sensors[static_cast<size_t>(k)].c_str());
    *out = std::move(c);
    return true;
}

std::vector<DriveNodeConfig> canCellDriveNodes(const Job& job, const std::vector<int>& ids) {
    CanCellConfig cell;
    std::string error;
    if (!makeCanCell(job, job.sim.period_s, nullptr, &cell, &error))
        throw std::invalid_argument(error);
    std::vector<DriveNodeConfig> out;
    for (int id : ids) {
        const auto it = std::find_if(cell.sim_drives.begin(), cell.sim_drives.end(),
                                     [id](const DriveNodeConfig& d) { return d.node == id; });
        if (it == cell.sim_drives.end()) {
            std::string drives;
            for (const DriveNodeConfig& d : cell.sim_drives)
                drives += (drives.empty() ? "" : ", ") + std::to_string(d.node);
            throw std::invalid_argument(
                "node " + std::to_string(id) +
                " is not a drive of the machine's CAN cell (its drives: " + drives + ")");
        }
        out.push_back(*it);
    }
    return out;
}

void tuneEngineForCanCell(EngineConfig& config, const CanCellConfig& cell, const Job& job,
                          double period_s) {
    tuneEngineForCan(config, cell.master, job.engine.home_speed_deg_s, period_s);
    // As for homing: a stopped encoder is still caught within 20 cycles at full speed, and a
    // TPDO a few cycles late at that speed is not taken for one.
    config.frozen_feedback_travel =
        std::max(config.frozen_feedback_travel, 20 * period_s * cell.fastest_linear_mm_s);
}

std::unique_ptr<CanCellMeter> makeCanCellMeter(const Job& job, const MotionProgram& program) {
    const CanCellEntry* entry = findCanCell(machineFor(job).id());
    return entry && entry->meter ? entry->meter(job, program) : nullptr;
}

} // namespace cutcell
