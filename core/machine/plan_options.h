#pragma once
// How a caller follows and stops a plan while it is made (the GUI plans off its thread).
#include <atomic>
#include <functional>

namespace cutcell {

struct PlanOptions {
    // Called now and then with the fraction done; planning stops early when *cancel is set.
    std::function<void(double)> progress;
    const std::atomic<bool>* cancel = nullptr;
    bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
};

} // namespace cutcell
