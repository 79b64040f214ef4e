#pragma once
// The flying saw's CSV exports (locale-independent numbers): the cam table (turntable angle,
// feed of both blades, tip radius), the carriage's cycle at the nominal line speed with its
// periods marked (AB .. HI), and the per-piece lengths of a simulation.
#include "core/machines/flying_saw/flying_saw_plan.h"
#include "core/machines/flying_saw/saw_simulation.h"

#include <string>

namespace cutcell {

std::string camTableCsv(const FlyingSawPlan& plan);

struct CycleRow {
    double t = 0, s = 0, v = 0, a = 0;
    const char* period = "AB";
};
// The carriage's s, v, a over one cycle at the nominal line speed (step dt), starting with
// wait_s of waiting: analytic, from the same profile functions the source runs.
std::vector<CycleRow> nominalCycle(const FlyingSawPlan& plan, double dt, double wait_s = 0.2);
std::string cycleCsv(const FlyingSawPlan& plan);

std::string piecesCsv(const SawSimResult& r);

} // namespace cutcell
