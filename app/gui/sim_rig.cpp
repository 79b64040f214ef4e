// The GUI's rig factory: the job's machine's simulated devices (devices/machines/, the same rig
// `cutcell-cli run` uses) under an engine thread, or the CANopen cell (can_rig.h).
#include "sim_rig.h"

#include "can_rig.h"
#include "core/machine/machine_registry.h"
#include "devices/machines/sim_rig_registry.h"
#include "production_record.h"

#include <cstdio>

namespace cutcell::app {
namespace {

class SimulatedMachineRig : public CutCell::ui::EngineRig {
  public:
    SimulatedMachineRig(const Job& job, ClockMode clock, std::unique_ptr<MachineSimRig> rig)
        : clock_(clock), rig_(std::move(rig)) {
        EngineConfig config;
        config.period_s = job.sim.period_s;
        rig_->configure(config);
        period_ = config.period_s;
        config.clock = clock;
        config.spec = job.engine;
        // As fast as possible the engine outruns any display: every 10th cycle keeps the
        // telemetry ring (8192 samples) from overflowing between two 30 Hz GUI ticks, so the
        // plots cover the whole cut. Real time keeps every cycle.
        if (clock == ClockMode::AsFastAsPossible) config.telemetry_every_n_cycles = 10;
        engine_ = std::make_unique<MotionEngine>(rig_->devices(), config);
        engine_->setRunRecord(productionRecord());
        engine_->startThread();
    }
    ~SimulatedMachineRig() override { engine_->stopThread(); }

    MotionEngine& engine() override { return *engine_; }
    std::string description() const override {
        // One template, so that the GUI can translate the line (tools/core_messages.py).
        char buf[200];
        std::snprintf(buf, sizeof buf, "%s, %.3g ms cycle, %s", rig_->description().c_str(),
                      period_ * 1000.0,
                      clock_ == ClockMode::RealTime ? "real time" : "as fast as possible");
        return buf;
    }

  private:
    ClockMode clock_;
    double period_ = 0;
    std::unique_ptr<MachineSimRig> rig_;
    std::unique_ptr<MotionEngine> engine_; // declared last: destroyed before the devices
};

std::unique_ptr<CutCell::ui::EngineRig> makeSimulatedMachineRig(const Job& job, ClockMode clock,
                                                                std::string* error) {
    try {
        // The devices start where the machine's program puts them (its reference); the run
        // controller loads its own program later. A job that does not plan (yet) still gets
        // devices, at zero, so the operator can jog and fix the job.
        const MachinePlan plan = machineFor(job).plan(job);
        MotionProgram atZero;
        const MotionProgram& start = plan.ok() && plan.program ? *plan.program : atZero;
        auto rig = makeSimulatedRig(job, start, error);
        if (!rig) return nullptr;
        return std::make_unique<SimulatedMachineRig>(job, clock, std::move(rig));
    } catch (const std::exception& e) {
        if (error) *error = e.what();
        return nullptr;
    }
}

} // namespace

std::unique_ptr<CutCell::ui::EngineRig> makeRig(const Job& job, ClockMode clock,
                                                std::string* error) {
    if (job.devices.kind == DeviceKind::CanOpen) return makeCanRig(job, error);
    if (job.devices.kind != DeviceKind::Simulated) {
        if (error)
            *error = std::string("devices.kind = \"") + toString(job.devices.kind) +
                     "\": this build of cutcell drives the simulated cell only";
        return nullptr;
    }
    return makeSimulatedMachineRig(job, clock, error);
}

} // namespace cutcell::app
