#pragma once
// A simulated torque-mode slider for the control-law motion source: one linear axis in CST
// (about 5 kg, force in N, mm) with a linear position sensor (sensor 0) of given resolution,
// run by the PD slider law. Used by the engine's tests and by `cutcell-cli bench`.
//
// Threading contract: build before the engine starts; then the devices belong to the engine
// thread (inject*() excepted).
#include "core/engine/motion_engine.h"
#include "core/engine/pd_slider_law.h"
#include "devices/sim/linear_position_sensor.h"
#include "devices/sim/simulated_torque_drive.h"

#include <memory>

namespace cutcell {

struct SliderRigOptions {
    PdSliderLawConfig law;
    double period_s = 0.001;
    double sensor_resolution_mm = 0.001;
};

class SliderRig {
  public:
    explicit SliderRig(const SliderRigOptions& o);
    EngineDevices devices();
    void configure(EngineConfig& config) const;
    std::shared_ptr<const MotionProgram> program() const { return program_; }
    PdSliderLaw& law() { return *law_; }
    SimulatedTorqueDrive& drive() { return drive_; }
    LinearPositionSensor& sensor() { return sensor_; }

  private:
    SliderRigOptions o_;
    SimulatedTorqueDrive drive_;
    LinearPositionSensor sensor_;
    std::shared_ptr<PdSliderLaw> law_;
    std::shared_ptr<MotionProgram> program_;
};

} // namespace cutcell
