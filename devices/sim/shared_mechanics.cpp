#include "devices/sim/shared_mechanics.h"

#include <algorithm>

namespace cutcell {

SharedMechanics::SharedMechanics(std::shared_ptr<CoupledMechanics> mechanics)
    : m_(std::move(mechanics)) {
    // Drives start without torque: every axis on its brake until its drive is enabled.
    for (int i = 0; i < m_->axisCount(); ++i)
        setHeld(i, true);
}

void SharedMechanics::setHeld(int axis, bool held) {
    held_[static_cast<size_t>(axis)] = held;
    m_->setHeld(axis, held);
}

void SharedMechanics::command(int axis, double torque, double load, double sensed) {
    torque_[axis] = torque;
    load_[axis] = load;
    sensed_[axis] = sensed;
    written_[static_cast<size_t>(axis)] = true;
    pending_ = true;
}

void SharedMechanics::update() {
    if (pending_) integrate();
}

double SharedMechanics::stepFor(int axis, double torque, double h, double period) {
    const auto a = static_cast<size_t>(axis);
    // Every step before the mechanics move sees the state the last integration left: the
    // feed-forward (and the torque returned) are those of that state.
    if (gravity_ && !roundGravityValid_) {
        JointVector q = JointVector::Zero();
        for (int i = 0; i < axisCount(); ++i)
            q[i] = m_->position(i);
        gravity_(q, roundGravity_);
        roundGravityValid_ = true;
    }
    command(axis, torque, 0, m_->position(axis));
    ahead_[a] += h;
    const double lim = m_->torqueLimit(axis);
    const double ff = gravity_ && !held_[a] ? roundGravity_[axis] : 0.0;
    const double given = std::clamp(torque + ff, -lim, lim);
    // Advance as far as every axis has given torque for (a little slack for rounding).
    const int n = axisCount();
    for (;;) {
        double least = ahead_[0];
        for (int i = 1; i < n; ++i)
            least = std::min(least, ahead_[static_cast<size_t>(i)]);
        if (least < period * (1 - 1e-6)) break;
        integrate();
        for (int i = 0; i < n; ++i)
            ahead_[static_cast<size_t>(i)] -= period;
    }
    return given;
}

void SharedMechanics::integrate() {
    const int n = axisCount();
    // Axes not written since the last step: sensed where they are, torque held.
    for (int i = 0; i < n; ++i)
        if (!written_[static_cast<size_t>(i)]) sensed_[i] = m_->position(i);
    if (gravity_)
        gravity_(sensed_, gravityTau_);
    else
        gravityTau_.setZero();
    total_.setZero();
    for (int i = 0; i < n; ++i) {
        const auto s = static_cast<size_t>(i);
        double u = torque_[i] + (held_[s] ? 0.0 : gravityTau_[i]);
        // An external load (collision, overload) adds to the motor torque; the total stays
        // within what the mechanics allow.
        if (load_[i] != 0) {
            const double lim = m_->torqueLimit(i);
            u = std::clamp(u, -lim, lim) + load_[i];
        }
        total_[i] = u;
    }
    m_->step(total_, applied_);
    written_.fill(false);
    pending_ = false;
    roundGravityValid_ = false;
}

} // namespace cutcell
