#pragma once
// A simulated saw as a process tool: on/off at once; the blade runs up to speed in spinup_s
// ("process OK" once at 95 % of its speed, linear run-up) and coasts down when switched off.
// Fault injection: the blade stalls (process not OK while on) and a saw fault code.
//
// Threading contract: ProcessTool calls from the engine thread; inject*() from any thread.
#include "core/devices/device_interfaces.h"

#include <atomic>
#include <cstdint>

namespace cutcell {

class SimulatedSaw : public ProcessTool {
  public:
    explicit SimulatedSaw(double spinup_s = 0.5) : spinup_(spinup_s > 0 ? spinup_s : 1e-9) {}

    void setOn(bool on) override { on_ = on; }
    ProcessToolFeedback read(double now_s) override {
        const double dt = last_ < 0 ? 0 : now_s - last_;
        last_ = now_s;
        const bool stalled = stall_.load(std::memory_order_relaxed);
        const double rate = dt / spinup_;
        speed_ = on_ && !stalled ? (speed_ + rate > 1 ? 1 : speed_ + rate)
                                 : (speed_ - rate < 0 ? 0 : speed_ - rate);
        ProcessToolFeedback fb;
        fb.on = on_;
        fb.fault_code = fault_.load(std::memory_order_relaxed);
        fb.process_ok = on_ && speed_ >= 0.95 - 1e-12 && fb.fault_code == 0;
        return fb;
    }
    void injectStall(bool on) { stall_.store(on); }
    void injectFault(std::uint32_t code) { fault_.store(code); }
    bool isOn() const { return on_; }
    double bladeSpeed() const { return speed_; } // fraction of nominal

  private:
    double spinup_;
    bool on_ = false;
    double speed_ = 0, last_ = -1;
    std::atomic<bool> stall_{false};
    std::atomic<std::uint32_t> fault_{0};
};

} // namespace cutcell
