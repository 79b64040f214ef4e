#pragma once
// The quick-return cutter's simulated machine: the crank drive in CST stepping the mechanism's
// dynamics (quick_return::CrankPlant: configuration-dependent inertia, gravity, the 400 N
// contact force over the workpiece, torque limit, friction, the disturbance torque) and the
// slider's linear scale (sensor 0, mm) reading y(q) + scale_offset.
//
// Threading contract: as SimulatedTorqueDrive (engine thread; probes between cycles).
#include "core/machines/quick_return/experiments.h"
#include "devices/machines/sim_rig_registry.h"
#include "devices/sim/linear_position_sensor.h"

namespace cutcell {

class QuickReturnCrankDrive : public AxisDrive {
  public:
    QuickReturnCrankDrive(const quick_return::ExperimentSetup& s, double q0);
    void activate() override;
    void deactivate() override;
    void quickStop() override { deactivate(); } // no position loop to hold with
    void faultReset() override {}
    DriveFeedback read(double now_s) override;
    void write(double) override { step(0); }
    bool setCommandMode(AxisCommandMode mode) override { return mode == AxisCommandMode::Torque; }
    AxisCommandMode commandMode() const override { return AxisCommandMode::Torque; }
    void writeTorque(double torque) override { step(torque); }

    double appliedTorque() const { return applied_; }
    std::uint64_t writes() const { return writes_; }
    const quick_return::CrankPlant& plant() const { return plant_; }

  private:
    void step(double torque);
    quick_return::ExperimentSetup s_;
    quick_return::CrankPlant plant_;
    DriveState state_ = DriveState::Disabled;
    double since_ = -1, applied_ = 0;
    std::uint64_t writes_ = 0;
};

// The slider as the scale sees it (mm).
class QuickReturnSliderProbe : public TruePositionProbe {
  public:
    explicit QuickReturnSliderProbe(const QuickReturnCrankDrive& d) : d_(d) {}
    double truePosition() const override { return 1000 * d_.plant().sliderPosition(); }
    double trueVelocity() const override { return 1000 * d_.plant().sliderVelocity(); }

  private:
    const QuickReturnCrankDrive& d_;
};

class QuickReturnSimRig : public MachineSimRig {
  public:
    QuickReturnSimRig(const quick_return::ExperimentSetup& s, const MotionProgram& program);
    EngineDevices devices() override;
    void configure(EngineConfig& config) const override;
    std::string description() const override {
        return "Simulated quick-return cutter: crank drive (CST) + slider scale";
    }
    QuickReturnCrankDrive& drive() { return drive_; }
    LinearPositionSensor& sensor() { return sensor_; }

  private:
    double period_;
    QuickReturnCrankDrive drive_;
    QuickReturnSliderProbe probe_;
    LinearPositionSensor sensor_;
};

} // namespace cutcell
