#pragma once
// The mechanics several simulated drives of one cell share (core/control/coupled_mechanics.h):
// each drive gives its own axis's torque, the hub integrates all axes at once, every drive then
// reads the new state. The order of a cycle is simulateCut()'s: sample all, control all, ONE
// mechanics step.
//
// Two ways of pacing the steps:
//  - in process (SimulatedDrive): write() stores the axis's torque and marks a step pending;
//    the first read of the next cycle (any drive: update()) performs the step with all stored
//    torques, then every read of that cycle sees the new state. An axis not written keeps its
//    last torque (zero-order hold, as a power stage does).
//  - on the CAN drive simulator (stepFor()): each axis steps by its own loop (one step of h
//    seconds per call) and the mechanics advance, one of their periods at a time, as far as
//    every axis has given a torque for: with one loop step per period (h = the period) that is
//    once every axis has stepped once since the last integration, the axis completing the round
//    integrating. An axis ahead of the mechanics (several steps before the others stepped)
//    sees the same state meanwhile and its last torque is the one held
//    (devices/machines/pipe_robot/pipe_robot_can_cell.cpp: how the simulator interleaves them).
//
// Brakes: setHeld(axis, true) while a drive has no torque (not enabled): the axis stands still.
// Gravity feed-forward (optional, setGravityFeedForward): each torque-giving (not held) axis
// gets the gravity torque at the positions its drive sensed added to its loop's torque, as
// simulateCut() does with a job's gravity_feedforward; a drive taking over from its brake then
// starts its loop from 0 (preloadTorque()), otherwise from the holding torque.
//
// Threading: the engine thread only (or the drive simulator's thread); no allocation, no lock.
#include "core/control/coupled_mechanics.h"

#include <array>
#include <functional>
#include <memory>

namespace cutcell {

class SharedMechanics {
  public:
    // g(q) of every axis at positions q (N m); must not allocate.
    using GravityFn = std::function<void(const JointVector& q, JointVector& tau)>;

    explicit SharedMechanics(std::shared_ptr<CoupledMechanics> mechanics);

    // Before the drives run.
    void setGravityFeedForward(GravityFn gravity) { gravity_ = std::move(gravity); }
    bool gravityFeedForward() const { return static_cast<bool>(gravity_); }

    CoupledMechanics& mechanics() { return *m_; }
    const CoupledMechanics& mechanics() const { return *m_; }
    int axisCount() const { return m_->axisCount(); }
    double position(int axis) const { return m_->position(axis); }
    double velocity(int axis) const { return m_->velocity(axis); }
    double torqueLimit(int axis) const { return m_->torqueLimit(axis); }
    // The torque the motor gave over the last step (N m).
    double applied(int axis) const { return applied_[axis]; }
    // What a drive taking over from its brake preloads its loop with: the holding torque, or 0
    // with gravity feed-forward (the feed-forward holds the axis).
    double preloadTorque(int axis) const {
        return gravityFeedForward() ? 0.0 : m_->holdingTorque(axis);
    }
    void setHeld(int axis, bool held);
    bool held(int axis) const { return held_[static_cast<size_t>(axis)]; }

    // The axis's loop torque for the next step, the load torque on it (fault injection: the
    // motor torque is clamped to its limit before the load adds, 0 = none) and the position
    // its drive closed the loop on (for the feed-forward).
    void command(int axis, double torque, double load, double sensed);
    // In process: the pending step, if any (the first read of a cycle).
    void update();
    // CAN: the axis's torque for its next h seconds; integrates every period all axes have
    // given a torque for (above). Returns the torque the motor gives (loop torque +
    // feed-forward, clamped to the limit). `period` is the mechanics' step (s).
    double stepFor(int axis, double torque, double h, double period);

  private:
    void integrate();

    std::shared_ptr<CoupledMechanics> m_;
    GravityFn gravity_;
    JointVector torque_ = JointVector::Zero(), load_ = JointVector::Zero();
    JointVector sensed_ = JointVector::Zero(), applied_ = JointVector::Zero();
    JointVector total_ = JointVector::Zero(), gravityTau_ = JointVector::Zero();
    JointVector roundGravity_ = JointVector::Zero(); // at the state a CAN round started from
    std::array<double, kMaxAxes> ahead_{}; // s each axis has given torque for, past the state
    std::array<bool, kMaxAxes> held_{}, written_{};
    bool pending_ = false, roundGravityValid_ = false;
};

} // namespace cutcell
