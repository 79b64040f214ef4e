#include "devices/machines/pipe_robot/pipe_robot_shared_mechanics.h"

#include "core/machines/pipe_robot/pipe_robot_mechanics.h"

namespace cutcell {

std::shared_ptr<SharedMechanics> makePipeRobotSharedMechanics(const Job& job, double period_s,
                                                              const JointVector& q0) {
    auto mechanics = std::make_shared<PipeRobotMechanics>(job, period_s);
    mechanics->setState(q0);
    auto hub = std::make_shared<SharedMechanics>(mechanics);
    // As simulateCut(): g(q) at the sensed positions added to each loop's torque.
    if (pipeRobotSpec(job).gravity_feedforward) {
        const PipeRobotMechanics* m = mechanics.get();
        hub->setGravityFeedForward(
            [m](const JointVector& q, JointVector& tau) { m->gravityTorques(q, tau); });
    }
    return hub;
}

double pipeRobotInPositionWindow(const Job& job, double linearWindow) {
    const PipeRobotSpec& spec = pipeRobotSpec(job);
    if (spec.plant_model != PlantModel::RigidBody) return linearWindow;
    for (const DriveTrainRow& d : spec.drives)
        if (d.coulomb_nm > 0) return kCoulombInPositionWindow;
    return linearWindow;
}

} // namespace cutcell
