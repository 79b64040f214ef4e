#include "profile_sim_rig.h"

#include "core/machines/profile_cutter/profile_cutter_program.h"
#include "devices/sim/profile_cutter_rig.h"

#include <cstdio>

namespace cutcell::app {
namespace {

class SimulatedProfileCutter : public CutCell::ui::EngineRig {
  public:
    // The program only sets the steppers' start counts (its reference); the run controller
    // loads its own copy of the program into the engine.
    SimulatedProfileCutter(const Job& job, ClockMode clock, const MotionProgram& program)
        : clock_(clock), period_(job.sim.period_s), rig_(job, program) {
        EngineConfig config;
        rig_.configure(config);
        config.clock = clock;
        config.spec = job.engine;
        // As for the robot (sim_rig.cpp): every 10th cycle in telemetry when as fast as possible.
        if (clock == ClockMode::AsFastAsPossible) config.telemetry_every_n_cycles = 10;
        engine_ = std::make_unique<MotionEngine>(rig_.devices(), config);
        engine_->startThread();
    }
    ~SimulatedProfileCutter() override { engine_->stopThread(); }

    MotionEngine& engine() override { return *engine_; }
    std::string description() const override {
        char buf[160];
        std::snprintf(
            buf, sizeof buf, "Simulated profile cutter: A + X steppers + torch, %.3g ms cycle, %s",
            period_ * 1000.0, clock_ == ClockMode::RealTime ? "real time" : "as fast as possible");
        return buf;
    }

  private:
    ClockMode clock_;
    double period_;
    ProfileCutterRig rig_;
    std::unique_ptr<MotionEngine> engine_; // declared last: destroyed before the devices
};

} // namespace

std::unique_ptr<CutCell::ui::EngineRig> makeProfileCutterRig(const Job& job, ClockMode clock,
                                                             std::string* error) {
    try {
        const auto program = buildProfileCutterProgram(job);
        return std::make_unique<SimulatedProfileCutter>(job, clock, *program);
    } catch (const std::exception& e) {
        if (error) *error = e.what();
        return nullptr;
    }
}

} // namespace cutcell::app
