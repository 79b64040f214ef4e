#pragma once
// Mechanics whose axes load each other (a rigid-body arm): the simulated drives of a cell share
// one, each sets its own axis's torque, and the mechanics integrate all axes at once. Positions in
// the axes' units (rad), torques in N m. Real-time safe: step() does not allocate or block.
#include "core/common/types.h"

namespace cutcell {

class CoupledMechanics {
  public:
    virtual ~CoupledMechanics() = default;
    virtual int axisCount() const = 0;
    virtual double position(int axis) const = 0;
    virtual double velocity(int axis) const = 0;
    virtual double torqueLimit(int axis) const = 0;
    // One control period with the torques held (each clamped to its axis's limit); `applied`
    // gets the torques the motors gave.
    virtual void step(const JointVector& torque, JointVector& applied) = 0;
    // The torque that holds the axis still where it is (gravity), N m: what a drive taking over
    // from its brake starts with.
    virtual double holdingTorque(int axis) const = 0;
    // A held axis stands still (its brake is on: a drive without torque); released, it moves.
    virtual void setHeld(int axis, bool held) = 0;
};

} // namespace cutcell
