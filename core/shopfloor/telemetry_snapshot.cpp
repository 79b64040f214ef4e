#include "core/shopfloor/telemetry_snapshot.h"

#include "core/common/types.h"

namespace cutcell::shopfloor {

CellSnapshot cellSnapshotOf(const Job& job, const MachineModule& module) {
    CellSnapshot s;
    s.machine_id = module.id();
    s.machine_name = module.title();
    s.job_name = job.name;
    s.state = "Idle";
    for (const AxisInfo& a : module.axes(job))
        s.axes.push_back({a.name, unitSymbol(a.unit), 0, 0});
    return s;
}

void applyTelemetry(CellSnapshot& s, const TelemetrySample& t) {
    s.state = toString(t.state);
    s.progress = t.progress;
    s.override_fraction = t.override_fraction;
    for (std::size_t i = 0; i < s.axes.size() && i < t.axis_count; ++i) {
        const double k = t.units[i] == AxisUnit::Rotary ? 180.0 / kPi : 1.0;
        s.axes[i].position = t.actual[static_cast<int>(i)] * k;
        s.axes[i].following_error = t.error[static_cast<int>(i)] * k;
    }
}

} // namespace cutcell::shopfloor
