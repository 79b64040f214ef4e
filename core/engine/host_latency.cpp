#include "core/engine/host_latency.h"

#include "core/engine/cycle_clock.h"

#include <ctime>
#include <thread>

namespace cutcell {

HostLatency measureHostWakeupLatency(double period_s, double duration_s,
                                     const RealtimeSettings& settings) {
    HostLatency out;
    JitterHistogram histogram; // the engine's own statistics, so the two p99 compare
    std::thread worker([&] {
        int dmaFd = -1;
        out.realtime = applyRealtime(settings, &dmaFd);
        const std::int64_t periodNs = static_cast<std::int64_t>(period_s * 1e9 + 0.5);
        const auto count = static_cast<std::uint64_t>(duration_s / period_s + 0.5);
        timespec next{};
        clock_gettime(CLOCK_MONOTONIC, &next);
        for (std::uint64_t k = 0; k < count; ++k) {
            next.tv_nsec += periodNs;
            while (next.tv_nsec >= 1000000000L) {
                next.tv_nsec -= 1000000000L;
                ++next.tv_sec;
            }
            while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr) != 0) {
            }
            timespec now{};
            clock_gettime(CLOCK_MONOTONIC, &now);
            const std::int64_t lateNs = (now.tv_sec - next.tv_sec) * 1000000000LL +
                                        (now.tv_nsec - next.tv_nsec);
            histogram.add(static_cast<double>(lateNs) / 1000.0);
        }
        releaseRealtime(dmaFd);
    });
    worker.join();
    out.samples = histogram.count();
    out.p50_us = histogram.percentile(0.50);
    out.p99_us = histogram.percentile(0.99);
    out.max_us = histogram.max();
    return out;
}

} // namespace cutcell
