#pragma once
// A simulated flying-saw cell for the master-axis motion source: a pipe line measured by a line
// encoder (the master, sensor 0), a carriage geared 1:1 to it (axis 0, linear, position mode),
// a saw feed on a cam table of the line's travel (axis 1, linear, position mode) and a saw as
// the process tool. Used by the engine's tests and by `cutcell-cli bench`.
//
// Threading contract: build before the engine starts; then the devices belong to the engine
// thread (inject*() and the cam double buffer excepted).
#include "core/engine/master_follower.h"
#include "core/engine/motion_engine.h"
#include "devices/sim/line_encoder.h"
#include "devices/sim/simulated_drive.h"
#include "devices/sim/simulated_saw.h"

#include <memory>

namespace cutcell {

struct FollowerRigOptions {
    LineEncoderConfig line;
    MasterFollowerConfig follower; // couplings and wait positions are set by the rig
    double period_s = 0.001;
    double feed_stroke_mm = 30; // the saw feed's cam: 0 -> stroke -> 0 over one cam period
    double cam_period_mm = 200;
    double saw_spinup_s = 0.2;
};

// A cam table of one feed stroke: 0 -> stroke -> 0 (cosine) over `period` of master travel.
CamTable feedStrokeCam(double stroke_mm, double period_mm, int points = 257);

class FollowerRig {
  public:
    explicit FollowerRig(const FollowerRigOptions& o);

    EngineDevices devices();
    void configure(EngineConfig& config) const;
    std::shared_ptr<const MotionProgram> program() const { return program_; }
    MasterFollower& follower() { return *follower_; }
    LineEncoder& line() { return line_; }
    SimulatedDrive& carriage() { return *carriage_; }
    SimulatedDrive& feed() { return *feed_; }
    SimulatedSaw& saw() { return saw_; }

  private:
    FollowerRigOptions o_;
    LineEncoder line_;
    std::unique_ptr<SimulatedDrive> carriage_, feed_;
    SimulatedSaw saw_;
    std::shared_ptr<MasterFollower> follower_;
    std::shared_ptr<MotionProgram> program_;
};

} // namespace cutcell
