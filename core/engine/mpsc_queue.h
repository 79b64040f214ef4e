#pragma once
// Bounded lock-free multi-producer / single-consumer queue of trivially copyable values
// (D. Vyukov's bounded queue: a sequence number per slot, a CAS on the write index).
//
// Threading contract: any number of threads may push(); one thread pops. Neither blocks:
// push() fails when the queue is full, pop() when it is empty. No allocation after the
// constructor.
#include <atomic>
#include <cstddef>
#include <memory>
#include <type_traits>

namespace cutcell {

template <typename T> class MpscQueue {
    static_assert(std::is_trivially_copyable_v<T>, "MpscQueue holds trivially copyable values");

  public:
    explicit MpscQueue(std::size_t capacity)
        : mask_(roundUp(capacity) - 1), slots_(new Slot[mask_ + 1]) {
        for (std::size_t i = 0; i <= mask_; ++i)
            slots_[i].seq.store(i, std::memory_order_relaxed);
    }

    bool push(const T& value) {
        std::size_t pos = write_.load(std::memory_order_relaxed);
        for (;;) {
            Slot& s = slots_[pos & mask_];
            const std::size_t seq = s.seq.load(std::memory_order_acquire);
            const auto diff = static_cast<std::ptrdiff_t>(seq) - static_cast<std::ptrdiff_t>(pos);
            if (diff == 0) {
                if (write_.compare_exchange_weak(pos, pos + 1, std::memory_order_relaxed)) {
                    s.value = value;
                    s.seq.store(pos + 1, std::memory_order_release);
                    return true;
                }
            } else if (diff < 0) {
                return false; // full
            } else {
                pos = write_.load(std::memory_order_relaxed);
            }
        }
    }

    bool pop(T& out) {
        const std::size_t pos = read_;
        Slot& s = slots_[pos & mask_];
        const std::size_t seq = s.seq.load(std::memory_order_acquire);
        if (static_cast<std::ptrdiff_t>(seq) - static_cast<std::ptrdiff_t>(pos + 1) < 0)
            return false;
        out = s.value;
        s.seq.store(pos + mask_ + 1, std::memory_order_release);
        read_ = pos + 1;
        return true;
    }

  private:
    struct Slot {
        std::atomic<std::size_t> seq{0};
        T value{};
    };
    static std::size_t roundUp(std::size_t n) {
        std::size_t p = 1;
        while (p < n)
            p <<= 1;
        return p;
    }

    const std::size_t mask_;
    std::unique_ptr<Slot[]> slots_;
    alignas(64) std::atomic<std::size_t> write_{0};
    alignas(64) std::size_t read_ = 0; // consumer only
};

} // namespace cutcell
