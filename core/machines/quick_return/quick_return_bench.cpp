// The quick-return cutter's figures for `cutcell-cli bench`: the MSE of each controller on
// experiment 1 and the velocity error of experiment 2 (default quick-return job).
#include "core/machines/quick_return/experiments.h"
#include "core/machines/quick_return/quick_return_module.h"

#include <chrono>
#include <string>

namespace cutcell {

void QuickReturnModule::addBenchFigures(bool quick, json::Object& out) const {
    (void)quick; // the experiments are short: the same in both modes
    using namespace quick_return;
    const Job job = defaultJob();
    ExperimentSetup s;
    if (!buildSetup(quickReturnSpec(job), &s).ok()) return;
    const auto t0 = std::chrono::steady_clock::now();
    for (ControllerKind k : kAllControllers) {
        const std::string c = toString(k);
        out.emplace_back("quick_return_exp1_mse_" + c, runTracking(s, k).mse);
    }
    for (ControllerKind k : kAllControllers) {
        const std::string c = toString(k);
        const CuttingResult r = runCutting(s, k);
        out.emplace_back("quick_return_exp2_completed_" + c, r.completed ? 1.0 : 0.0);
        out.emplace_back("quick_return_exp2_verr_max_m_s_" + c, r.velocity_error_max);
        out.emplace_back("quick_return_exp2_verr_rms_m_s_" + c, r.velocity_error_rms);
    }
    out.emplace_back("quick_return_experiments_seconds",
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

} // namespace cutcell
