#pragma once
// Pacing and self-measurement of the engine thread.
//
// CycleTimer sleeps until absolute deadlines on CLOCK_MONOTONIC. The sleep is a futex wait
// with an absolute timeout (Linux), so another thread can wake it early with wake() (the
// emergency stop does): the engine then pushes the stop to the devices at once instead of
// at the next period. Elsewhere it falls back to clock_nanosleep(TIMER_ABSTIME).
//
// JitterHistogram keeps 1 us bins (0 .. 20 ms, then an overflow bin) in relaxed atomics:
// the engine thread adds, any thread reads percentiles. Allocated once; add() is lock-free.
#include <atomic>
#include <cstdint>
#include <memory>

namespace cutcell {

std::int64_t monotonicNowNs();

class CycleTimer {
  public:
    // Sleeps until deadline_ns (monotonic) or until wake() is called. Returns true when woken
    // early (the deadline is still ahead), false when the deadline was reached.
    bool sleepUntil(std::int64_t deadline_ns);
    // Any thread; never blocks.
    void wake();

  private:
    std::atomic<std::uint32_t> word_{0};
};

class JitterHistogram {
  public:
    static constexpr int kBins = 20000; // 1 us each
    JitterHistogram();
    void add(double us);
    void clear();
    double percentile(double p) const; // upper edge of the bin holding the p-quantile
    double max() const { return max_.load(std::memory_order_relaxed); }
    std::uint64_t count() const { return count_.load(std::memory_order_relaxed); }

  private:
    std::unique_ptr<std::atomic<std::uint32_t>[]> bins_;
    std::atomic<std::uint32_t> overflow_{0};
    std::atomic<std::uint64_t> count_{0};
    std::atomic<double> max_{0};
};

} // namespace cutcell
