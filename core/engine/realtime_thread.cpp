#include "core/engine/realtime_thread.h"

#include <cerrno>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CUTCELL_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) ||                         \
    __has_feature(memory_sanitizer)
#define CUTCELL_SANITIZED 1
#endif
#endif

namespace cutcell {
namespace {

#ifndef CUTCELL_SANITIZED
// Touches this much of the thread's stack once, so the cycle never faults a stack page in.
constexpr std::size_t kStackPrefaultBytes = 256 * 1024;

[[gnu::noinline]] void prefaultStack() {
    volatile unsigned char buf[kStackPrefaultBytes];
    for (std::size_t i = 0; i < sizeof buf; i += 4096)
        buf[i] = 0;
}
#endif

// Items appended to a fixed buffer, "; " between them (truncates, never overflows).
struct Line {
    char* out;
    unsigned long size;
    unsigned long n = 0;
    __attribute__((format(printf, 2, 3))) void item(const char* fmt, ...) {
        if (n > 0) append("; ");
        va_list ap;
        va_start(ap, fmt);
        if (n < size) {
            const int k = std::vsnprintf(out + n, size - n, fmt, ap);
            if (k > 0) n += static_cast<unsigned long>(k);
        }
        va_end(ap);
    }
    void append(const char* text) {
        if (n >= size) return;
        const int k = std::snprintf(out + n, size - n, "%s", text);
        if (k > 0) n += static_cast<unsigned long>(k);
    }
};

} // namespace

RealtimeStatus applyRealtime(const RealtimeSettings& s, int* dmaFd) {
    RealtimeStatus st;
    st.applied = true;
    *dmaFd = -1;
    if (s.lock_memory) {
#ifdef CUTCELL_SANITIZED
        st.lock_error = ENOTSUP;
#else
        // MCL_FUTURE only where locking is unbounded (root or an unlimited RLIMIT_MEMLOCK):
        // under a finite limit it would make later allocations of the whole process fail.
        // The engine's own buffers are allocated before its thread starts (MCL_CURRENT).
        rlimit lim{};
        const bool unbounded = ::geteuid() == 0 || (::getrlimit(RLIMIT_MEMLOCK, &lim) == 0 &&
                                                    lim.rlim_cur == RLIM_INFINITY);
        if (mlockall(MCL_CURRENT | (unbounded ? MCL_FUTURE : 0)) == 0) {
            st.memory_locked = true;
            prefaultStack();
        } else {
            st.lock_error = errno;
        }
#endif
    }
    if (s.cpu >= 0) {
        st.cpu = s.cpu;
        cpu_set_t set;
        CPU_ZERO(&set);
        if (s.cpu >= CPU_SETSIZE) {
            st.cpu_error = EINVAL;
        } else {
            CPU_SET(s.cpu, &set);
            st.cpu_error = pthread_setaffinity_np(pthread_self(), sizeof set, &set);
            st.cpu_pinned = st.cpu_error == 0;
        }
    }
    if (s.priority > 0) {
        sched_param sp{};
        sp.sched_priority = s.priority;
        st.priority_error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp);
        // Read back: the policy actually in force is what counts.
        int policy = 0;
        sched_param got{};
        if (st.priority_error == 0 && pthread_getschedparam(pthread_self(), &policy, &got) == 0 &&
            policy == SCHED_FIFO) {
            st.rt_priority_granted = true;
            st.priority = got.sched_priority;
        } else if (st.priority_error == 0) {
            st.priority_error = EPERM;
        }
    }
    if (s.cpu_dma_latency) {
        const int fd = ::open("/dev/cpu_dma_latency", O_RDWR | O_CLOEXEC);
        if (fd < 0) {
            st.dma_latency_error = errno;
        } else {
            const std::int32_t zero = 0;
            if (::write(fd, &zero, sizeof zero) == static_cast<ssize_t>(sizeof zero)) {
                st.dma_latency_held = true;
                *dmaFd = fd; // the request holds while the descriptor is open
            } else {
                st.dma_latency_error = errno;
                ::close(fd);
            }
        }
    }
    return st;
}

void releaseRealtime(int dmaFd) {
    if (dmaFd >= 0) ::close(dmaFd);
}

bool describeRealtime(const RealtimeSettings& s, const RealtimeStatus& st, char* out,
                      unsigned long size) {
    // Items joined by "; ", each a whole sentence (the GUI translates the line item by item:
    // tools/core_messages.py lists the items' templates).
    bool allOk = true;
    Line line{out, size};
    if (size > 0) out[0] = '\0';
    if (s.priority <= 0) {
        line.item("Real-time: normal scheduler (no SCHED_FIFO asked)");
    } else if (st.rt_priority_granted) {
        line.item("Real-time: SCHED_FIFO %d granted", st.priority);
    } else {
        allOk = false;
        line.item("Real-time: SCHED_FIFO %d NOT granted (%s: needs CAP_SYS_NICE or an rtprio "
                  "limit, so jitter follows the normal scheduler)",
                  s.priority, std::strerror(st.priority_error));
    }
    if (!s.lock_memory)
        line.item("memory not locked (not asked)");
    else if (st.memory_locked)
        line.item("memory locked");
    else {
        allOk = false;
        line.item("memory NOT locked (%s)",
                  st.lock_error == ENOTSUP ? "sanitizer build" : std::strerror(st.lock_error));
    }
    if (s.cpu >= 0) {
        if (st.cpu_pinned)
            line.item("pinned to CPU %d", s.cpu);
        else {
            allOk = false;
            line.item("NOT pinned to CPU %d (%s)", s.cpu, std::strerror(st.cpu_error));
        }
    }
    if (s.cpu_dma_latency) {
        if (st.dma_latency_held)
            line.item("/dev/cpu_dma_latency held at 0 us");
        else {
            allOk = false;
            line.item("/dev/cpu_dma_latency NOT held (%s)", std::strerror(st.dma_latency_error));
        }
    }
    return allOk;
}

std::size_t realtimeLinePiece(std::string_view line, std::size_t maxChars) {
    if (line.size() <= maxChars) return line.size();
    const std::size_t sep = line.rfind("; ", maxChars);
    return sep == std::string_view::npos || sep == 0 ? maxChars : sep;
}

} // namespace cutcell
