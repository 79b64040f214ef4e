#pragma once
// The mechanics behind a simulated drive node, when they are not the node's own joint model
// (J q'' + b q' = u): e.g. a crank driving a mechanism whose inertia and loads depend on the
// crank angle. The node's power stage gives a torque; the plant moves. Positions in the axis
// units (rad or mm), torques in N m (or N).
//
// Threading: driven by one DriveNode on the drive simulator's thread; other nodes of the same
// simulator (an encoder on the mechanism) may read it there.
namespace cutcell::canopen {

class TorquePlant {
  public:
    virtual ~TorquePlant() = default;
    virtual double position() const = 0;
    virtual double velocity() const = 0;
    // Applies `torque` (clamped to the motor's limit) for h seconds; returns the torque applied.
    virtual double step(double torque, double h) = 0;
    // The rated torque (0x6076): 1000 per mille of the node's torque objects.
    virtual double ratedTorque() const = 0;
    // The axis's brake, when the mechanics have one: on (held: the axis stands still) while the
    // node gives no torque (out of Operation Enabled and Quick Stop Active). Default: none.
    virtual void setHeld(bool /*held*/) {}
    // The torque that holds the axis where it is (N m): what the position loop starts with
    // when the node takes over from its brake (0: the loop starts from rest, as without).
    virtual double holdingTorque() const { return 0; }
    // Mechanics that other nodes of the simulator drive as well (coupled axes): at a SYNC the
    // simulator then runs the position loops of all its nodes step by step in turn (every
    // node's step j before any node's step j + 1), so each loop step sees the mechanics as the
    // others left them (DriveNode::hasDeferredStep). Default: the node runs its loop alone.
    virtual bool sharedWithOtherNodes() const { return false; }
};

} // namespace cutcell::canopen
