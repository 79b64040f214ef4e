#pragma once
// A serial chain in standard Denavit-Hartenberg convention:
//   A_i = Rz(theta_i + offset_i) * Tz(d_i) * Tx(a_i) * Rx(alpha_i).
// Value type only; solvers are built from it.
#include "core/common/types.h"

#include <array>
#include <limits>
#include <vector>

namespace cutcell {

struct DhLink {
    double alpha_rad = 0;
    double a_mm = 0;
    double d_mm = 0;
    double theta_offset_rad = 0;
    // Limits default to "unbounded" (lowest(), not min(): see CONVENTIONS.md).
    double min_rad = std::numeric_limits<double>::lowest();
    double max_rad = std::numeric_limits<double>::max();
};

Pose dhTransform(const DhLink& link, double theta);

class DhChain {
  public:
    DhChain() = default;
    explicit DhChain(std::vector<DhLink> links) : links_(std::move(links)) {}

    size_t size() const { return links_.size(); }
    const DhLink& link(size_t i) const { return links_[i]; }

    // Pose of the last frame in the base frame.
    Pose forward(const double* q) const;
    // Poses of frames 0..n (frame 0 = base identity): frames[i + 1] = A_1 ... A_{i+1}.
    void frames(const double* q, Pose* out) const;

  private:
    std::vector<DhLink> links_;
};

} // namespace cutcell
