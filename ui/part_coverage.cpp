#include "ui/part_coverage.h"

#include <algorithm>

namespace CutCell::ui {

void PartCoverage::begin() {
    reached_s_ = 0;
    gaps_.clear();
}

void PartCoverage::recoverFrom(double t_s) {
    if (t_s > reached_s_ + kJoinS) gaps_.push_back({reached_s_, t_s});
    reached_s_ = std::max(reached_s_, t_s); // the recovery's run cuts on from here
}

void PartCoverage::stoppedAt(double t_s) {
    reached_s_ = std::max(reached_s_, t_s);
}

} // namespace CutCell::ui
