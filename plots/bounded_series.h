#pragma once
// A bounded time series: a ring of samples (t, v[0..channels-1]) that drops the oldest sample
// when full and counts the drops. Storage is allocated once (constructor / setCapacity), so
// append() never allocates.
//
// Threading: not synchronised. Use it from one thread (the GUI thread drains the engine's
// lock-free telemetry on a timer and appends here).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cutcell::plots {

class BoundedSeries {
  public:
    BoundedSeries(int channels, int capacity);

    int channels() const { return channels_; }
    int capacity() const { return capacity_; }
    int size() const { return size_; }
    bool empty() const { return size_ == 0; }
    // Samples dropped (oldest first) because the ring was full, since the last clear().
    std::uint64_t dropped() const { return dropped_; }
    // Samples ever appended since the last clear() (kept + dropped).
    std::uint64_t appended() const { return appended_; }

    // Changing the capacity or the channel count clears the series.
    void setCapacity(int capacity);
    void setChannels(int channels);
    void clear();

    // Copies `channels()` values from v (missing values, when n < channels, are NaN).
    void append(double t, const double* v, int n);

    // Chronological access: i = 0 is the oldest kept sample.
    double time(int i) const { return t_[slot(i)]; }
    double value(int i, int channel) const {
        return v_[slot(i) * static_cast<size_t>(channels_) + static_cast<size_t>(channel)];
    }
    double lastTime() const { return time(size_ - 1); }

  private:
    size_t slot(int i) const {
        return (static_cast<size_t>(head_) + static_cast<size_t>(i)) %
               static_cast<size_t>(capacity_);
    }

    int channels_;
    int capacity_;
    int head_ = 0; // slot of the oldest sample
    int size_ = 0;
    std::uint64_t dropped_ = 0;
    std::uint64_t appended_ = 0;
    std::vector<double> t_;
    std::vector<double> v_;
};

} // namespace cutcell::plots
