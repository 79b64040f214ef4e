#include "devices/sim/simulated_torch.h"

namespace cutcell {

void SimulatedTorch::setOn(bool on) {
    if (on && !on_) onSince_ = -1;
    on_ = on;
}

TorchFeedback SimulatedTorch::read(double now_s) {
    if (on_ && onSince_ < 0) onSince_ = now_s;
    TorchFeedback fb;
    fb.on = on_;
    fb.fault_code = fault_.load(std::memory_order_relaxed);
    fb.process_ok = on_ && now_s - onSince_ + 1e-9 >= ignitionDelay_ &&
                    !arcLost_.load(std::memory_order_relaxed) && fb.fault_code == 0;
    return fb;
}

} // namespace cutcell
