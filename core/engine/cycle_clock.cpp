#include "core/engine/cycle_clock.h"

#include <cerrno>
#include <cmath>
#include <ctime>

#ifdef __linux__
#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace cutcell {

std::int64_t monotonicNowNs() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

namespace {
timespec toTimespec(std::int64_t ns) {
    timespec ts{};
    ts.tv_sec = static_cast<time_t>(ns / 1000000000LL);
    ts.tv_nsec = static_cast<long>(ns % 1000000000LL);
    return ts;
}
} // namespace

bool CycleTimer::sleepUntil(std::int64_t deadline_ns) {
#ifdef __linux__
    for (;;) {
        if (word_.exchange(0, std::memory_order_acq_rel) != 0)
            return monotonicNowNs() < deadline_ns;
        if (monotonicNowNs() >= deadline_ns) return false;
        const timespec ts = toTimespec(deadline_ns);
        // FUTEX_WAIT_BITSET takes an absolute CLOCK_MONOTONIC timeout; returns at once if
        // word_ is no longer 0 (a wake() came in between).
        const long rc =
            syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&word_), FUTEX_WAIT_BITSET_PRIVATE,
                    0u, &ts, nullptr, FUTEX_BITSET_MATCH_ANY);
        if (rc != 0 && errno == ETIMEDOUT) return false;
    }
#else
    const timespec ts = toTimespec(deadline_ns);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
    }
    return false;
#endif
}

void CycleTimer::wake() {
    word_.store(1, std::memory_order_release);
#ifdef __linux__
    syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&word_), FUTEX_WAKE_PRIVATE, 1, nullptr,
            nullptr, 0);
#endif
}

JitterHistogram::JitterHistogram() : bins_(new std::atomic<std::uint32_t>[kBins]) {
    clear();
}

void JitterHistogram::clear() {
    for (int i = 0; i < kBins; ++i)
        bins_[static_cast<size_t>(i)].store(0, std::memory_order_relaxed);
    overflow_.store(0, std::memory_order_relaxed);
    count_.store(0, std::memory_order_relaxed);
    max_.store(0, std::memory_order_relaxed);
}

void JitterHistogram::add(double us) {
    if (!(us >= 0)) us = 0;
    const double b = std::floor(us);
    if (b < kBins)
        bins_[static_cast<size_t>(b)].fetch_add(1, std::memory_order_relaxed);
    else
        overflow_.fetch_add(1, std::memory_order_relaxed);
    count_.fetch_add(1, std::memory_order_relaxed);
    if (us > max_.load(std::memory_order_relaxed)) max_.store(us, std::memory_order_relaxed);
}

double JitterHistogram::percentile(double p) const {
    const std::uint64_t n = count();
    if (n == 0) return 0;
    const auto rank = static_cast<std::uint64_t>(std::ceil(p * static_cast<double>(n)));
    std::uint64_t seen = 0;
    for (int i = 0; i < kBins; ++i) {
        seen += bins_[static_cast<size_t>(i)].load(std::memory_order_relaxed);
        if (seen >= rank && seen > 0) return i + 1.0;
    }
    return max();
}

} // namespace cutcell
