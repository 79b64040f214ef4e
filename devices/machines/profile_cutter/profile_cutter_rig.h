#pragma once
// The simulated 2-axis NC pipe profile cutter (seed 002) for the motion engine: the A axis
// (pipe turn, rad) and the X carriage (mm) as open-loop steppers behind a pulse card, and a
// torch. Resolutions and the card's rate limit come from the job's profile_cutter keys:
//   A: 2 pi / (steps_per_rev_a * pulses_per_step_a) rad per pulse, X: mm_per_pulse_x.
//
// Threading contract: build and configure before the engine starts; the devices are then used
// by the engine thread only (see SimulatedStepper).
#include "core/engine/motion_engine.h"
#include "core/engine/motion_program.h"
#include "core/job/job.h"
#include "devices/sim/simulated_stepper.h"
#include "devices/sim/simulated_torch.h"

namespace cutcell {

class ProfileCutterRig {
  public:
    ProfileCutterRig(const Job& job, const MotionProgram& program);

    EngineDevices devices();
    // Engine settings of a stepper machine: the in-position window is half a pulse (the
    // count can be no closer to the set-point), the job's period, clock left to the caller.
    void configure(EngineConfig& config) const;

    SimulatedStepper& a() { return a_; }
    SimulatedStepper& x() { return x_; }
    SimulatedTorch& torch() { return torch_; }

  private:
    SimulatedStepperConfig aCfg_, xCfg_;
    SimulatedStepper a_, x_;
    SimulatedTorch torch_;
    double period_s_;
};

} // namespace cutcell
