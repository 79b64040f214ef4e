#pragma once
// Offline simulation of a flying-saw job (`cutcell-cli simulate`, the bench, the tests): the
// simulated line and roller encoder, the same motion source the engine runs, the carriage's
// servo (PID + plant, the simulated rig's model), the cut positions on the pipe, and the
// length gauge after the saw that corrects the encoder's scale from the measured pieces.
// The turntable and feeds are taken as commanded (they do not move the cut along the pipe).
#include "core/machines/flying_saw/cut_length_meter.h"
#include "core/machines/flying_saw/flying_saw_plan.h"
#include "core/machines/flying_saw/flying_saw_source.h"
#include "core/machines/flying_saw/flying_saw_spec.h"

#include <functional>
#include <vector>

namespace cutcell {

struct SawSimOptions {
    double period_s = 0.001;
    double max_time_s = 1e5;
    // Called once per cycle after the source's update (tests: change the queue, look at state).
    std::function<void(double t, FlyingSawSource& source)> each_cycle;
    bool record_cycle = false; // keep the carriage's s, v, a of the first full cycle
};

struct CycleSample {
    double t = 0, s = 0, v = 0, a = 0;
    int phase = 0;
};

struct SawSimResult {
    bool completed = false;
    std::string problem; // why it stopped early (the source's fault)
    double simulated_s = 0;
    std::vector<CutRecord> cuts;
    std::vector<PieceRecord> pieces;
    LengthStats stats;
    double max_following_error_mm = 0; // carriage, in sync
    double max_return_miss_mm = 0;     // set-point at the end of each return - wait position
    double first_sync_master_mm = 0;
    double max_sync_error_mm = 0; // set-point - (x_sync + line - S) while in sync
    double final_scale = 1;
    std::vector<CycleSample> cycle; // record_cycle
};

SawSimResult simulateFlyingSaw(const FlyingSawSpec& spec, const FlyingSawPlan& plan,
                               const SawSimOptions& options = {});

// The line time the whole queue needs (what simulateFlyingSaw runs): the pieces at the line's
// speed and a few cycles to start and end. A queue over `options.max_time_s` is refused before
// any work with the figures (sawSimWorkProblem, "" when it fits).
double sawSimExpectedSeconds(const FlyingSawSpec& spec, const FlyingSawPlan& plan);
std::string sawSimWorkProblem(const FlyingSawSpec& spec, const FlyingSawPlan& plan,
                              const SawSimOptions& options = {});

// The JSON report of `simulate` (per piece, stats, periods) and a few lines for the terminal.
std::string sawReportJson(const FlyingSawSpec& spec, const FlyingSawPlan& plan,
                          const SawSimResult& r);
std::string sawReportText(const FlyingSawSpec& spec, const FlyingSawPlan& plan,
                          const SawSimResult& r);

} // namespace cutcell
