#include "sim_rig.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"

#include "can_rig.h"
#include "profile_sim_rig.h"

#include "devices/sim/simulated_drive.h"
#include "devices/sim/simulated_torch.h"

#include <array>
#include <cstdio>

namespace cutcell::app {
namespace {

class SimulatedRig : public CutCell::ui::EngineRig {
  public:
    SimulatedRig(const Job& job, ClockMode clock) : clock_(clock), period_(job.sim.period_s) {
        EngineDevices devices;
        for (size_t i = 0; i < drives_.size(); ++i) {
            SimulatedDriveConfig cfg;
            cfg.gains = job.controller[i];
            cfg.plant = job.plant[i];
            cfg.period_s = job.sim.period_s;
            drives_[i] = std::make_unique<SimulatedDrive>(cfg);
            devices.axes[i] = drives_[i].get();
        }
        torch_ = std::make_unique<SimulatedTorch>();
        devices.torch = torch_.get();
        EngineConfig config;
        config.period_s = job.sim.period_s;
        config.clock = clock;
        config.spec = job.engine;
        config.gains = job.controller;
        // As fast as possible the engine outruns any display: every 10th cycle keeps the
        // telemetry ring (8192 samples) from overflowing between two 30 Hz GUI ticks, so the
        // plots cover the whole cut. Real time keeps every cycle.
        if (clock == ClockMode::AsFastAsPossible) config.telemetry_every_n_cycles = 10;
        engine_ = std::make_unique<MotionEngine>(devices, config);
        engine_->startThread();
    }
    ~SimulatedRig() override { engine_->stopThread(); }

    MotionEngine& engine() override { return *engine_; }
    std::string description() const override {
        char buf[128];
        std::snprintf(buf, sizeof buf, "Simulated cell: 6 drives + torch, %.3g ms cycle, %s",
                      period_ * 1000.0,
                      clock_ == ClockMode::RealTime ? "real time" : "as fast as possible");
        return buf;
    }

  private:
    ClockMode clock_;
    double period_;
    std::array<std::unique_ptr<SimulatedDrive>, kAxisCount> drives_;
    std::unique_ptr<SimulatedTorch> torch_;
    std::unique_ptr<MotionEngine> engine_; // declared last: destroyed before the devices
};

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
    if (job.machine == cutcell::kProfileCutterId) return makeProfileCutterRig(job, clock, error);
    try {
        return std::make_unique<SimulatedRig>(job, clock);
    } catch (const std::exception& e) {
        if (error) *error = e.what();
        return nullptr;
    }
}

} // namespace cutcell::app
