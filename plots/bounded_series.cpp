#include "plots/bounded_series.h"

#include <algorithm>
#include <limits>

namespace cutcell::plots {

BoundedSeries::BoundedSeries(int channels, int capacity)
    : channels_(std::max(1, channels)), capacity_(std::max(1, capacity)) {
    t_.assign(static_cast<size_t>(capacity_), 0.0);
    v_.assign(static_cast<size_t>(capacity_) * static_cast<size_t>(channels_), 0.0);
}

void BoundedSeries::setCapacity(int capacity) {
    capacity_ = std::max(1, capacity);
    t_.assign(static_cast<size_t>(capacity_), 0.0);
    v_.assign(static_cast<size_t>(capacity_) * static_cast<size_t>(channels_), 0.0);
    clear();
}

void BoundedSeries::setChannels(int channels) {
    channels_ = std::max(1, channels);
    v_.assign(static_cast<size_t>(capacity_) * static_cast<size_t>(channels_), 0.0);
    clear();
}

void BoundedSeries::clear() {
    head_ = 0;
    size_ = 0;
    dropped_ = 0;
    appended_ = 0;
}

void BoundedSeries::append(double t, const double* v, int n) {
    int index;
    if (size_ < capacity_) {
        index = (head_ + size_) % capacity_;
        ++size_;
    } else {
        index = head_; // overwrite the oldest
        head_ = (head_ + 1) % capacity_;
        ++dropped_;
    }
    ++appended_;
    const size_t i = static_cast<size_t>(index);
    t_[i] = t;
    double* row = v_.data() + i * static_cast<size_t>(channels_);
    for (int c = 0; c < channels_; ++c)
        row[c] = (v && c < n) ? v[c] : std::numeric_limits<double>::quiet_NaN();
}

} // namespace cutcell::plots
