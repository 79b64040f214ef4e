#pragma once
// The pipe robot's mechanics (core/machines/pipe_robot/pipe_robot_mechanics.h) shared by the six
// drives of a simulated cell: the in-process simulated drives and the CAN drive simulator run
// the same plant as simulateCut(), with its gravity feed-forward when the job asks for it.
#include "core/job/job.h"
#include "devices/sim/shared_mechanics.h"

#include <memory>

namespace cutcell {

// The job's mechanics (plant_model: linear or rigid body) stepping every period_s, at rest at
// q0, every axis on its brake.
std::shared_ptr<SharedMechanics> makePipeRobotSharedMechanics(const Job& job, double period_s,
                                                              const JointVector& q0);

// How close to the first cut point the engine waits for the axes before a cut (rad; the engine's
// in_position_window). The linear plant, and the rigid-body plant without Coulomb friction,
// settle to rounding (linearWindow, 1e-12 by default). With Coulomb friction the axes stick and
// slip (hunt) around their set-points against the integral action of the position loops, in a
// band of a few 1e-5 rad on the default job, and never come within rounding of them: the window
// is then kCoulombInPositionWindow.
inline constexpr double kCoulombInPositionWindow = 1e-4;
double pipeRobotInPositionWindow(const Job& job, double linearWindow);

} // namespace cutcell
