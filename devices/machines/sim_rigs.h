#pragma once
// The factories of the machines' simulated rigs (one file each in this folder).
#include "devices/machines/sim_rig_registry.h"

namespace cutcell {

std::unique_ptr<MachineSimRig> makePipeRobotSimRig(const Job& job, const MotionProgram& program);
std::unique_ptr<MachineSimRig> makeFlyingSawSimRig(const Job& job, const MotionProgram& program);
std::unique_ptr<MachineSimRig> makeProfileCutterSimRig(const Job& job,
                                                       const MotionProgram& program);
std::unique_ptr<MachineSimRig> makeQuickReturnSimRig(const Job& job, const MotionProgram& program);
std::unique_ptr<MachineSimRig> makeSectionSteelSimRig(const Job& job,
                                                      const MotionProgram& program);

} // namespace cutcell
