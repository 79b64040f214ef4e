// The pipe robot's CAN cell: six rotary CSP drives with the job's own controller. Behind them,
// in the rigid-body model, one shared PipeRobotMechanics (the plant simulateCut() runs): each
// node drives its axis through a per-axis view. In the linear model each node keeps its own
// joint plant (the job's plant[] rows), as the linear mechanics would step them anyway.
//
// Pacing of the shared mechanics (SharedMechanics::stepFor): at a SYNC every node samples its
// TPDO; the views say the mechanics are shared (TorquePlant::sharedWithOtherNodes), so the
// drive simulator then runs the nodes' loop steps of the cycle in turn, every node's step j
// before any node's step j + 1 (DriveNode::runDeferredStep). The mechanics, built with the
// nodes' loop step as their period, integrate one period as soon as every node has given a
// torque for it, i.e. once every node has stepped once since the last integration: every TPDO
// of a SYNC samples the same state, and each loop step of every node sees the state the last
// integration left - simulateCut()'s sample all, control all, step once, at the loop rate.
// Several sub-steps per SYNC (a cycle longer than the 1 ms loop: n steps of cycle/n) thus give
// n integrations per SYNC, each with fresh torques of all six nodes. Were a node's sub-steps
// run back to back instead (a simulator without the interleaving), the mechanics would still
// keep time - they advance as far as every node has given torque for - but the nodes run first
// would close their loops on the state of the SYNC for the whole cycle, holding their last
// torque (their loops then sample the coupled plant at the SYNC rate, which a 10 ms cycle with
// the seed's gains does not survive). While no SYNC comes, the nodes' free-running loops
// (several steps each, by the wall clock, run back to back) advance the mechanics as far as the
// slowest of them: the axes out of Operation Enabled are on their brakes then anyway.
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "devices/machines/can_cell_machine.h"
#include "devices/machines/pipe_robot/pipe_robot_shared_mechanics.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace cutcell {
namespace {

// One axis of the shared mechanics as a node's torque plant.
class MechanicsAxisView : public canopen::TorquePlant {
  public:
    MechanicsAxisView(std::shared_ptr<SharedMechanics> hub, int axis, double period)
        : hub_(std::move(hub)), axis_(axis), period_(period) {}
    double position() const override { return hub_->position(axis_); }
    double velocity() const override { return hub_->velocity(axis_); }
    double step(double torque, double h) override {
        return hub_->stepFor(axis_, torque, h, period_);
    }
    double ratedTorque() const override { return hub_->torqueLimit(axis_); }
    void setHeld(bool held) override { hub_->setHeld(axis_, held); }
    double holdingTorque() const override { return hub_->preloadTorque(axis_); }
    bool sharedWithOtherNodes() const override { return true; }

  private:
    std::shared_ptr<SharedMechanics> hub_;
    int axis_;
    double period_; // the mechanics' step
};

} // namespace

bool fillPipeRobotCanCell(CanCellBuilder& b, std::string*) {
    const PipeRobotSpec& spec = pipeRobotSpec(b.job);
    std::shared_ptr<SharedMechanics> hub;
    double loopStep = 0;
    if (spec.plant_model == PlantModel::RigidBody) {
        JointVector q0 = JointVector::Zero();
        for (int a = 0; a < b.cell.axis_count; ++a)
            q0[a] = b.startOf(a);
        // The nodes' loop step (DriveNode::onSync: n equal steps of at most the loop period).
        const double maxLoop = b.driveNode(0, {}, {}).max_loop_period_s;
        const int steps = std::max(1, static_cast<int>(std::ceil(b.period_s / maxLoop - 1e-9)));
        loopStep = b.period_s / steps;
        hub = makePipeRobotSharedMechanics(b.job, loopStep, q0);
    }
    for (int a = 0; a < b.cell.axis_count; ++a) {
        const auto i = static_cast<size_t>(a);
        canopen::DriveNodeConfig d = b.driveNode(a, spec.controller[i], spec.plant[i]);
        if (hub) d.mechanics = std::make_shared<MechanicsAxisView>(hub, a, loopStep);
        b.cell.sim_drives.push_back(d);
    }
    return true;
}

} // namespace cutcell
