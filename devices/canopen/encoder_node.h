#pragma once
// One simulated CiA 406 encoder as a CANopen slave, without any transport: frames in, frames
// out. NMT slave, boot-up and heartbeat producer (0x1017), expedited SDO server for its small
// object dictionary (0x1000 device type = profile 406, 0x1017, 0x1018 identity, 0x6004
// position value, TPDO1 0x1800/0x1A00 with the CiA 301 mapping procedure) and TPDO1 with the
// position value on every SYNC, sampled at the SYNC instant.
//
// What it measures comes from a function of time (s): a pipe line's travel seen by a measuring
// roller, a slider seen by its scale. Counts = round(position * counts_per_unit). The time is
// the simulator's wall clock, or with sync_period_s > 0 the SYNC clock: the first SYNC's wall
// time plus sync_period_s per SYNC since - the clock of the simulated drives, whose mechanics
// advance one communication cycle per SYNC. A line read on the wall clock moves on while SYNCs
// are late or skipped (a loaded host, an engine that skips missed cycles, --clock fast) and the
// drives do not: the carriage would see the line jump against its own world.
//
// Fault injection: heartbeats stop (the master's consumer notices), TPDOs stop (a frozen
// encoder on a live node: the master notices SYNCs left unanswered).
//
// Threading: not thread-safe; DriveSimulator drives it from its own thread.
#include "devices/canopen/can_frame.h"
#include "devices/canopen/nmt.h"
#include "devices/canopen/sdo.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace cutcell::canopen {

struct EncoderNodeConfig {
    int node = 32;
    double counts_per_unit = 20;                  // counts per mm (or per rad)
    std::function<double(double now_s)> position; // units (mm); null: 0
    double sync_period_s = 0;                     // > 0: position() on the SYNC clock (above)
    double heartbeat_stop_after_s = -1;           // < 0: never (after this long Operational)
    double pdo_stop_after_s = -1;                 // < 0: never
};

class EncoderNode {
  public:
    explicit EncoderNode(EncoderNodeConfig c);

    void boot(double now_s, std::vector<CanFrame>& out);
    void handle(const CanFrame& in, double now_s, std::vector<CanFrame>& out);
    void tick(double now_s, std::vector<CanFrame>& out);

    void stopHeartbeat() { heartbeatStopped_ = true; }
    void stopPdo() { pdoStopped_ = true; }

    int node() const { return c_.node; }
    NmtState nmtState() const { return nmt_; }
    std::int32_t lastCounts() const { return counts_; }
    std::uint64_t syncCount() const { return syncs_; }

  private:
    void resetCommunication();
    void onSdo(const CanFrame& in, double now_s, std::vector<CanFrame>& out);
    std::uint32_t read(SdoAddress a, std::uint32_t& v, int& size, double now_s) const;
    std::uint32_t write(SdoAddress a, std::uint32_t v, int size);
    std::int32_t sample(double now_s) const;
    double measuredAt(double now_s) const; // the time position() is asked for

    EncoderNodeConfig c_;
    NmtState nmt_ = NmtState::BootUp;
    std::uint16_t heartbeatMs_ = 0;
    std::uint8_t syncOverflow_ = 0; // 0x1019
    double nextHeartbeat_s_ = 0;
    double operationalSince_s_ = -1;
    bool heartbeatStopped_ = false, pdoStopped_ = false;
    std::uint32_t tpdoCobId_ = 0;
    std::uint8_t tpdoType_ = 1;
    std::uint8_t mapCount_ = 0;
    std::uint32_t mapEntry_ = 0;
    std::int32_t counts_ = 0;
    std::uint64_t syncs_ = 0;
    double firstSync_s_ = -1; // wall time of the first SYNC (SYNC clock)
};

} // namespace cutcell::canopen
