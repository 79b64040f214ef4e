#include "core/shopfloor/telemetry_snapshot.h"

#include "core/common/types.h"

#include <algorithm>
#include <utility>
#include <vector>

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

LastRunFigures lastRunFiguresOf(const json::Value& tracking, double cycle_time_s,
                                std::string outcome) {
    LastRunFigures f;
    f.cycle_time_s = cycle_time_s;
    f.outcome = std::move(outcome);
    const json::Value* joints = tracking.isObject() ? tracking.find("joints") : nullptr;
    if (!joints || !joints->isArray()) return f;
    struct AxisFigures {
        std::string unit;
        double max, rms;
    };
    std::vector<AxisFigures> axes;
    for (const json::Value& j : joints->asArray())
        for (const char* unit : {"deg", "mm"}) {
            const json::Value* mx = j.find(std::string("max_abs_error_") + unit);
            const json::Value* rms = j.find(std::string("rms_error_") + unit);
            if (mx && rms && mx->isNumber() && rms->isNumber())
                axes.push_back({unit, mx->asNumber(), rms->asNumber()});
        }
    for (const AxisFigures& a : axes)
        if (f.error_unit.empty() || a.max > f.tracking_max) {
            f.tracking_max = a.max;
            f.error_unit = a.unit;
        }
    for (const AxisFigures& a : axes) // RMS of the same unit only (deg and mm do not compare)
        if (a.unit == f.error_unit) f.tracking_rms = std::max(f.tracking_rms, a.rms);
    return f;
}

} // namespace cutcell::shopfloor
