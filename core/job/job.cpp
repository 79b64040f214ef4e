#include "core/job/job.h"

namespace cutcell {

const char* toString(CutTarget t) {
    return t == CutTarget::Branch ? "branch" : "main";
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

} // namespace cutcell
