#pragma once
// State shared between one CanOpenDrive (engine thread) and the master thread, lock-free:
// every field is a std::atomic written by one side and read by the other.
#include "devices/canopen/cia402.h"
#include "devices/canopen/nmt.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <unistd.h>

namespace cutcell::canopen {

// Adds one to an eventfd: wakes the master thread; never blocks (EFD_NONBLOCK), no allocation.
inline void postEventFd(int fd) {
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = ::write(fd, &one, sizeof one);
}

struct NodeShared {
    // Engine -> master.
    std::atomic<std::uint8_t> goal{static_cast<std::uint8_t>(DriveGoal::Disabled)};
    std::atomic<std::uint32_t> fault_reset_requests{0}; // counter: each increment is one request
    std::atomic<bool> urgent{false};                    // send the controlword now (RPDO2)
    // Target in counts, tagged with the enable epoch the engine had seen when it wrote it:
    // bits 63..32 epoch, 31..0 counts. The master uses a target only if its epoch is current,
    // so set-points written before the drive reported Enabled never reach it (no jump).
    std::atomic<std::uint64_t> tagged_target{0};
    // Targets written so far (one per engine cycle) and the last kTargetRing of them (tagged as
    // above, index seq % kTargetRing): when several cycles' SYNCs are due at once (this
    // thread's partner was held up) the master sends each cycle's own target with its SYNC, so
    // the drives get the engine's sequence of targets, only closer together.
    static constexpr std::uint64_t kTargetRing = 16;
    std::atomic<std::uint64_t> write_seq{0};
    std::array<std::atomic<std::uint64_t>, kTargetRing> targets{};

    // Master -> engine.
    std::atomic<std::uint16_t> statusword{0};
    std::atomic<std::int32_t> actual_counts{0};
    std::atomic<double> velocity_counts_s{0};
    std::atomic<std::int16_t> torque_permille{0}; // 0x6077
    std::atomic<std::int64_t> tpdo_ns{0};         // steady clock of the last TPDO
    std::atomic<std::uint64_t> tpdo_count{0};
    // write_seq of the last SYNC sent before the last TPDO came: the engine's cycle that TPDO
    // answers, or a later one when it came late (the feedback's age reads low, never high).
    std::atomic<std::uint64_t> tpdo_seq{0};
    std::atomic<std::uint8_t> nmt{static_cast<std::uint8_t>(NmtState::Unknown)};
    std::atomic<std::int64_t> heartbeat_ns{0};  // steady clock of the last heartbeat
    std::atomic<std::uint32_t> enable_epoch{0}; // +1 each time the drive enters Operation Enabled
    std::atomic<bool> configured{false};        // start-up done, PDOs running
    // Master-side fault (heartbeat lost, SDO refused, bus off...): a CiA 301 EMCY code or an
    // SDO abort code; 0 = none. Latched until a fault reset finds the cause gone.
    std::atomic<std::uint32_t> master_fault{0};
    std::atomic<std::uint16_t> last_emcy{0}; // error code of the last EMCY (0 after reset)
    // CST drives: the rated torque 0x6076 read at start-up (N m or N; 0 = not read yet): the
    // scale of the target torque 0x6071 and the torque actual 0x6077 (per mille of it).
    std::atomic<double> rated_torque{0};

    static std::uint64_t tag(std::uint32_t epoch, std::int32_t counts) {
        return (static_cast<std::uint64_t>(epoch) << 32) | static_cast<std::uint32_t>(counts);
    }
    static std::uint32_t epochOf(std::uint64_t t) { return static_cast<std::uint32_t>(t >> 32); }
    static std::int32_t countsOf(std::uint64_t t) {
        return static_cast<std::int32_t>(t & 0xFFFFFFFFu);
    }
};

} // namespace cutcell::canopen
