#include "core/job/job.h"

namespace cutcell {

const char* toString(CutTarget t) {
    return t == CutTarget::Branch ? "branch" : "main";
}
const char* toString(CutMethod m) {
    return m == CutMethod::StaticPipe ? "static_pipe" : "rotating_pipe";
}
const char* toString(DeviceKind k) {
    return k == DeviceKind::Simulated ? "simulated" : "canopen";
}
const char* toString(StopCategory c) {
    return c == StopCategory::Cat0 ? "cat0" : "cat1";
}

int sensorNodeId(const DeviceSpec& d, int axisCount, int k) {
    const int id = d.sensor_node_ids[static_cast<size_t>(k)];
    return id != 0 ? id : axisCount + 1 + k;
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

} // namespace cutcell
