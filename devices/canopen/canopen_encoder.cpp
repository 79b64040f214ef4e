#include "devices/canopen/canopen_encoder.h"

#include <algorithm>

namespace cutcell::canopen {

SensorReading CanOpenEncoder::read(double) {
    SensorReading r;
    r.position = shared_.actual_counts.load(std::memory_order_acquire) / countsPerUnit_;
    if (clock_) { // as CanOpenDrive::read: 0 when the TPDO answered the last SYNC
        const std::uint64_t answered = shared_.tpdo_seq.load(std::memory_order_relaxed);
        const std::uint64_t now = clock_->load(std::memory_order_relaxed);
        r.age_cycles = static_cast<std::uint8_t>(
            answered > 0 && now > answered ? std::min<std::uint64_t>(now - answered, 255) : 0);
    }
    r.velocity = shared_.velocity_counts_s.load(std::memory_order_acquire) / countsPerUnit_;
    r.fault_code = shared_.master_fault.load(std::memory_order_acquire);
    r.valid =
        r.fault_code == 0 && shared_.configured.load(std::memory_order_acquire) &&
        shared_.tpdo_count.load(std::memory_order_acquire) > 0 &&
        static_cast<NmtState>(shared_.nmt.load(std::memory_order_acquire)) == NmtState::Operational;
    return r;
}

} // namespace cutcell::canopen
