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
        const auto toNs = [](const timespec& t) { return t.tv_sec * 1000000000LL + t.tv_nsec; };
        const auto toTs = [](std::int64_t ns) {
            timespec t{};
            t.tv_sec = static_cast<time_t>(ns / 1000000000LL);
            t.tv_nsec = static_cast<long>(ns % 1000000000LL);
            return t;
        };
        timespec ts{};
        clock_gettime(CLOCK_MONOTONIC, &ts);
        const std::int64_t end = toNs(ts) + static_cast<std::int64_t>(duration_s * 1e9);
        std::int64_t next = toNs(ts) + periodNs;
        while (next < end) {
            const timespec deadline = toTs(next);
            while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &deadline, nullptr) != 0) {
            }
            clock_gettime(CLOCK_MONOTONIC, &ts);
            const std::int64_t now = toNs(ts);
            histogram.add(static_cast<double>(now - next) / 1000.0);
            next += periodNs;
            // Like cyclictest (and the engine): deadlines already missed are skipped, not
            // measured as a burst of late wake-ups.
            while (next < now)
                next += periodNs;
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
