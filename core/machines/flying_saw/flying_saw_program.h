#pragma once
// The flying saw's program for the engine (a MasterAxis source) and the drive model its
// simulations use (offline and the simulated rig alike).
#include "core/engine/motion_program.h"
#include "core/job/job.h"
#include "core/machines/flying_saw/flying_saw_plan.h"
#include "core/machines/flying_saw/flying_saw_source.h"

#include <memory>
#include <string>

namespace cutcell {

FlyingSawConfig sawSourceConfig(const FlyingSawSpec& spec, const FlyingSawPlan& plan);

// The program: axes carriage (mm), turntable (rad), feed 1, feed 2 (mm); sensor 0 = the line
// encoder; the saw is the process tool. A fresh source each call (it keeps run state).
std::shared_ptr<MotionProgram> buildFlyingSawProgram(const Job& job, const FlyingSawSpec& spec,
                                                     const FlyingSawPlan& plan,
                                                     const std::string& jobText);

// The servo model of every axis in simulation: the core's PID + first-order filter on
// J q'' + b q' = u (bandwidth ~100 rad/s, as the other simulated linear axes).
// The saw's words and counts: pieces (each with its length), no path length.
RunTerms flyingSawTerms();
PidGains sawAxisGains();
JointPlantParams sawAxisPlant();

} // namespace cutcell
