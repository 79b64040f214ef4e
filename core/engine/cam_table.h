#pragma once
// A cam table (slave position over one master period) of fixed capacity, and a single-writer /
// single-reader double buffer that lets a non-cycle thread replace a table while the cycle
// runs: the writer fills the back table and publishes it; the cycle takes it at its next
// cam-cycle boundary (never in the middle of a cam cycle), so the slave does not jump when the
// new table starts where the old one ends. Nothing here allocates after construction.
#include <array>
#include <atomic>
#include <cmath>
#include <string>

namespace cutcell {

struct CamTable {
    static constexpr int kCapacity = 1024;
    // slave[i] at master distance i * period / (count - 1); periodic: slave[0] == slave[count-1].
    std::array<double, kCapacity> slave{};
    int count = 0;
    double period = 0; // master distance of one cam cycle (mm or rad of the master)

    // Cubic Hermite with central-difference slopes (periodic wrap): C1 in the master.
    double at(double m) const {
        if (count < 2 || !(period > 0)) return count > 0 ? slave[0] : 0;
        double x = std::fmod(m, period);
        if (x < 0) x += period;
        const int n = count - 1; // intervals
        const double h = period / n;
        int i = static_cast<int>(x / h);
        if (i >= n) i = n - 1;
        const double t = (x - i * h) / h;
        auto y = [&](int k) { // periodic index over the n distinct points
            k %= n;
            if (k < 0) k += n;
            return slave[static_cast<size_t>(k)];
        };
        const double y0 = y(i), y1 = y(i + 1);
        const double m0 = 0.5 * (y(i + 1) - y(i - 1)), m1 = 0.5 * (y(i + 2) - y(i));
        const double t2 = t * t, t3 = t2 * t;
        return (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * y1 +
               (t3 - t2) * m1;
    }
};

// Empty when the table can be used; else what is wrong (outside the cycle: allocates).
inline std::string camTableProblem(const CamTable& t) {
    if (t.count < 2 || t.count > CamTable::kCapacity)
        return "cam table: count = " + std::to_string(t.count) + " is outside 2 .. " +
               std::to_string(CamTable::kCapacity);
    if (!(t.period > 0) || !std::isfinite(t.period))
        return "cam table: period = " + std::to_string(t.period) + " must be > 0";
    for (int i = 0; i < t.count; ++i)
        if (!std::isfinite(t.slave[static_cast<size_t>(i)]))
            return "cam table: slave[" + std::to_string(i) + "] is not a number";
    if (std::fabs(t.slave[0] - t.slave[static_cast<size_t>(t.count - 1)]) > 1e-9)
        return "cam table: a periodic table must end where it starts (slave[0] = " +
               std::to_string(t.slave[0]) +
               ", slave[last] = " + std::to_string(t.slave[static_cast<size_t>(t.count - 1)]) + ")";
    return {};
}

// Writer: any one non-cycle thread. Reader: the engine cycle.
template <class T> class CycleDoubleBuffer {
  public:
    // Writer: the table to fill, or null while the last published one was not taken yet.
    T* beginWrite() { return pending_.load(std::memory_order_acquire) ? nullptr : &slots_[back()]; }
    void publish() { pending_.store(true, std::memory_order_release); }
    // Reader: the table in use.
    const T& front() const { return slots_[front_.load(std::memory_order_relaxed)]; }
    // Reader, at a boundary: switches to the published table; true if it did.
    bool takePublished() {
        if (!pending_.load(std::memory_order_acquire)) return false;
        front_.store(back(), std::memory_order_relaxed);
        pending_.store(false, std::memory_order_release);
        return true;
    }
    bool pending() const { return pending_.load(std::memory_order_acquire); }
    // Outside any run (no concurrent reader): sets the table in use.
    T& frontForSetup() { return slots_[front_.load(std::memory_order_relaxed)]; }

  private:
    unsigned back() const { return 1u - front_.load(std::memory_order_relaxed); }
    std::array<T, 2> slots_{};
    std::atomic<unsigned> front_{0};
    std::atomic<bool> pending_{false};
};

} // namespace cutcell
