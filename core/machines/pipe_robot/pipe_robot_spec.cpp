#include "core/machines/pipe_robot/pipe_robot_spec.h"

namespace cutcell {

const char* toString(CutMethod m) {
    return m == CutMethod::StaticPipe ? "static_pipe" : "rotating_pipe";
}

std::array<DhRow, kAxisCount> seedDhTable() {
    // alpha_deg, a_mm, d_mm, theta_offset_deg, min_deg, max_deg (seed Table 1).
    return {{{90, 0, 260, 0, -180, 180},
             {90, 0, 371, 0, -140, 140},
             {0, 157, 0, 0, -45, 45},
             {0, 120, 0, 0, -90, 90},
             {90, 50, 0, 0, -145, 90},
             {0, 0, 210, 0, -180, 180}}};
}

const PipeRobotSpec& pipeRobotSpec(const Job& job) {
    return readSpec<PipeRobotSpec>(job.machine_spec, "the pipe robot's");
}

PipeRobotSpec& pipeRobotSpec(Job& job) {
    return editSpec<PipeRobotSpec>(job.machine_spec, "the pipe robot's");
}

} // namespace cutcell
