#pragma once
// Bounded lock-free single-producer / single-consumer ring of plain fixed-size values.
//
// Threading contract: exactly one thread calls push(), exactly one (other) thread calls pop().
// Both return at once: push() fails when the ring is full (the producer counts the loss),
// pop() fails when it is empty. The storage is allocated once, in the constructor.
#include <atomic>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>

namespace cutcell {

// T: a fixed-size value whose copy neither allocates nor throws (plain structs, fixed-size
// Eigen matrices; Eigen types are not "trivially copyable" for the standard, hence the weaker
// check).
template <typename T> class SpscRing {
    static_assert(std::is_copy_assignable_v<T> && std::is_default_constructible_v<T>,
                  "SpscRing holds plain fixed-size values");

  public:
    // capacity is rounded up to a power of two.
    explicit SpscRing(std::size_t capacity)
        : mask_(roundUp(capacity) - 1), slots_(new T[mask_ + 1]) {}

    std::size_t capacity() const { return mask_ + 1; }

    bool push(const T& value) {
        const std::size_t w = write_.load(std::memory_order_relaxed);
        if (w - read_.load(std::memory_order_acquire) > mask_) return false;
        slots_[w & mask_] = value;
        write_.store(w + 1, std::memory_order_release);
        return true;
    }

    bool pop(T& out) {
        const std::size_t r = read_.load(std::memory_order_relaxed);
        if (r == write_.load(std::memory_order_acquire)) return false;
        out = slots_[r & mask_];
        read_.store(r + 1, std::memory_order_release);
        return true;
    }

    // Approximate when called from a third thread; exact from either end.
    std::size_t size() const {
        return write_.load(std::memory_order_acquire) - read_.load(std::memory_order_acquire);
    }

  private:
    static std::size_t roundUp(std::size_t n) {
        std::size_t p = 1;
        while (p < n)
            p <<= 1;
        return p;
    }

    const std::size_t mask_;
    std::unique_ptr<T[]> slots_;
    // Separate cache lines so producer and consumer do not share one.
    alignas(64) std::atomic<std::size_t> write_{0};
    alignas(64) std::atomic<std::size_t> read_{0};
};

} // namespace cutcell
