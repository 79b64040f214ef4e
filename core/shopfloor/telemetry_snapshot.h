#pragma once
// The moving part of a cell's snapshot from the engine's telemetry: state, progress, the
// override and every axis in its own unit (deg on rotary axes, mm on linear ones). What the run
// made is the run model's to say (the engine counts path points on some machines, not pieces).
// The station (GUI), `cutcell-cli shopfloor` and `bench-shopfloor` fill it the same way.
#include "core/engine/engine_types.h"
#include "core/json/json.h"
#include "core/machine/machine_module.h"
#include "core/shopfloor/cell_snapshot.h"

namespace cutcell::shopfloor {

// Machine id, title, job name and the axes' names and units; state "Idle".
CellSnapshot cellSnapshotOf(const Job& job, const MachineModule& module);
// What a telemetry sample says (axes beyond the snapshot's list are left out).
void applyTelemetry(CellSnapshot& snapshot, const TelemetrySample& t);

// A run's figures from its tracking report (a run report's top level, or summary.json's
// "tracking"): the largest joint error over the axes and its unit (deg on rotary axes, mm on
// linear ones, as the report's keys say), and the largest RMS among the axes of that unit.
LastRunFigures lastRunFiguresOf(const json::Value& tracking, double cycle_time_s,
                                std::string outcome);

} // namespace cutcell::shopfloor
