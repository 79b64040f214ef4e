#pragma once
// A simulated cutting torch: on/off at once, the arc established ignition_delay_s after
// switching on. Fault injection: arc lost (the arc goes out while the torch is on) and a
// torch fault code.
//
// Threading contract: Torch calls come from the engine thread only; inject*() from any thread.
#include "core/devices/device_interfaces.h"

#include <atomic>
#include <cstdint>

namespace cutcell {

class SimulatedTorch : public Torch {
  public:
    explicit SimulatedTorch(double ignition_delay_s = 0.02) : ignitionDelay_(ignition_delay_s) {}

    void setOn(bool on) override;
    TorchFeedback read(double now_s) override;

    void injectArcLoss(bool on) { arcLost_.store(on); }
    void injectFault(std::uint32_t code) { fault_.store(code); }
    void clearInjections() {
        arcLost_.store(false);
        fault_.store(0);
    }
    bool isOn() const { return on_; }

  private:
    double ignitionDelay_;
    bool on_ = false;
    double onSince_ = -1; // -1: stamped at the next read
    std::atomic<bool> arcLost_{false};
    std::atomic<std::uint32_t> fault_{0};
};

} // namespace cutcell
