#pragma once
// A process control that corrects a program's set-point in the engine cycle, after the motion
// source: the torch height control (THC) moves the torch along its own axis to hold the cut
// height on a pipe that is not the planned cylinder. A machine builds it with its program
// (MotionProgram::correction); the engine knows no machine and no process.
//
// Engine thread only; start(), update() and fill() must not allocate, lock or block.
#include "core/engine/motion_source.h"
#include "core/sim/tracking_stats.h"

namespace cutcell {

class SetpointCorrection {
  public:
    virtual ~SetpointCorrection() = default;
    // A run's motion begins (after the approach and the ignition): no correction, new figures.
    virtual void start(const SourceInput& in) = 0;
    // After the source's update of this cycle: may move out.position / out.velocity (the
    // set-point the drives get) and writes out.process. tool_on: the engine commands the tool.
    virtual void update(const SourceInput& in, bool tool_on, SourceOutput& out) = 0;
    // The run's figures at its end (summary.json).
    virtual void fill(TrackingReport& report) const = 0;
};

} // namespace cutcell
