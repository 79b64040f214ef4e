#include "devices/machines/can_cells.h"

#include "core/machine/machine_registry.h"
#include "core/machines/flying_saw/flying_saw_program.h"
#include "core/machines/flying_saw/pipe_line_sim.h"
#include "core/machines/quick_return/crank_plant.h"
#include "core/machines/quick_return/quick_return_spec.h"
#include "core/machines/section_steel/section_steel_spec.h"

#include "devices/canopen/engine_tuning.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

namespace cutcell {

using namespace canopen;

namespace {

// The quick-return mechanism behind the crank drive (CST): the crank's torque steps the
// Whitworth dynamics (configuration-dependent inertia, gravity, the contact force over the
// workpiece, friction, the disturbance torque), as QuickReturnCrankDrive does in process.
class CrankMechanics : public TorquePlant {
  public:
    CrankMechanics(const quick_return::ExperimentSetup& s, double q0)
        : s_(s), plant_(s.law.dims, s.plant) {
        plant_.setState(q0, 0);
    }
    double position() const override { return plant_.state().q; }
    double velocity() const override { return plant_.state().dq; }
    double step(double torque, double h) override {
        const double dist =
            s_.disturbance_amplitude * std::sin(2 * std::numbers::pi * s_.disturbance_hz * t_);
        t_ += h;
        const bool on = torque != 0;
        return plant_.step(torque, on ? dist : 0.0, h);
    }
    double ratedTorque() const override { return s_.plant.torque_limit; }
    double sliderMm() const { return 1000 * plant_.sliderPosition(); }

  private:
    quick_return::ExperimentSetup s_;
    quick_return::CrankPlant plant_;
    double t_ = 0;
};

double startOf(const MotionProgram* program, int axis) {
    return program ? program->reference[axis] : 0.0;
}

DriveNodeConfig driveNode(const Job& job, int axis, bool linear, const PidGains& gains,
                          const JointPlantParams& plant, double period_s) {
    DriveNodeConfig c;
    c.node = job.devices.node_ids[static_cast<size_t>(axis)];
    c.gains = gains;
    c.plant = plant;
    c.counts_per_rad = countsPerRad(job.devices.counts_per_unit[static_cast<size_t>(axis)], linear);
    c.max_loop_period_s = std::min(0.001, period_s);
    return c;
}

} // namespace

bool makeCanCell(const Job& job, double period_s, const MotionProgram* program, CanCellConfig* out,
                 std::string* error) {
    const MachineModule& module = machineFor(job);
    if (std::string why; !module.supportsCanOpen(&why)) {
        if (error) *error = why;
        return false;
    }
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
    auto addEncoder = [&](int k, double countsPerUnit, std::function<double(double)> position) {
        MasterNodeConfig n;
        n.node = sensorNodeId(job.devices, c.axis_count, k);
        n.counts_per_unit = countsPerUnit;
        n.linear = true;
        n.encoder = true;
        c.master.nodes.push_back(n);
        EncoderNodeConfig e;
        e.node = n.node;
        e.counts_per_unit = countsPerUnit;
        e.position = std::move(position);
        c.sim_encoders.push_back(std::move(e));
    };

    if (const auto* steel = job.machine_spec.as<section_steel::SectionSteelSpec>()) {
        for (int a = 0; a < c.axis_count; ++a) {
            DriveNodeConfig d = driveNode(job, a, false, steel->controller[static_cast<size_t>(a)],
                                          steel->plant[static_cast<size_t>(a)], period_s);
            d.start_position_rad = startOf(program, a);
            c.sim_drives.push_back(d);
        }
    } else if (const auto* saw = job.machine_spec.as<FlyingSawSpec>()) {
        for (int a = 0; a < c.axis_count; ++a) {
            const bool linear = c.master.nodes[static_cast<size_t>(a)].linear;
            DriveNodeConfig d = driveNode(job, a, linear, sawAxisGains(), sawAxisPlant(), period_s);
            d.start_position_rad = startOf(program, a);
            // 20 mm (or deg) of following error before the drive faults itself: the engine's
            // limit (following_error_limit_mm) acts first.
            d.following_error_window_counts = static_cast<std::uint32_t>(
                std::lround(20 * job.devices.counts_per_unit[static_cast<size_t>(a)]));
            c.sim_drives.push_back(d);
        }
        c.fastest_linear_mm_s = saw->carriage.max_speed_mm_s;
        // The line encoder: the pipe line's travel as the measuring roller reads it (speed
        // profile with ramps, steps and noise, slip, the roller's resolution), counted by a
        // CiA 406 encoder of that resolution.
        PipeLineConfig lc;
        lc.speed_mm_s = saw->lineSpeedMmS();
        lc.resolution_mm = saw->encoderResolutionMm();
        lc.sim = saw->line_sim;
        lc.duration_s = 3600;
        auto line = std::make_shared<PipeLineSim>(lc);
        // On the SYNC clock, as the simulated drives move (encoder_node.h): the line advances
        // one period per SYNC, however late the SYNCs come on a loaded host.
        addEncoder(0, 1.0 / lc.resolution_mm, [line](double t) { return line->read(t).position; });
        c.sim_encoders.back().sync_period_s = period_s;
    } else if (const auto* qr = job.machine_spec.as<QuickReturnSpec>()) {
        quick_return::ExperimentSetup s;
        std::string problem;
        if (!buildSetup(*qr, &s, &problem)) {
            if (error) *error = problem;
            return false;
        }
        s.plant.contact = qr->experiment == quick_return::Experiment::Cutting;
        const double q0 = program ? program->start_position[0] : s.law.stroke.q_bottom + 0.01;
        auto crank = std::make_shared<CrankMechanics>(s, q0);
        DriveNodeConfig d = driveNode(job, 0, false, {}, {}, period_s);
        d.mechanics = crank;
        d.plant.torque_limit_nm = s.plant.torque_limit;
        c.sim_drives.push_back(d);
        // The slider's linear scale (mm) on the mechanism the crank drive moves.
        addEncoder(0, 1.0 / (1000 * qr->scale_resolution),
                   [crank](double) { return crank->sliderMm(); });
    } else {
        // The pipe robot: the job's own controller and joint plant per axis (rotary, CSP).
        std::vector<int> ids;
        for (int a = 0; a < c.axis_count; ++a)
            ids.push_back(job.devices.node_ids[static_cast<size_t>(a)]);
        c.sim_drives = nodesFromJob(job, ids);
        for (DriveNodeConfig& d : c.sim_drives)
            d.max_loop_period_s = std::min(0.001, period_s);
    }
    c.description = std::to_string(csp + cst) + " CiA 402 drives (" +
                    (cst == 0   ? std::string("CSP")
                     : csp == 0 ? std::string("CST")
                                : std::to_string(csp) + " CSP, " + std::to_string(cst) + " CST") +
                    ")";
    for (int k = 0; k < c.sensor_count; ++k)
        c.description += " + CiA 406 encoder " +
                         std::to_string(sensorNodeId(job.devices, c.axis_count, k)) + " (" +
                         sensors[static_cast<size_t>(k)] + ")";
    *out = std::move(c);
    return true;
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
    if (job.machine_spec.as<FlyingSawSpec>()) return makeFlyingSawCanMeter(job, program);
    return nullptr;
}

} // namespace cutcell
