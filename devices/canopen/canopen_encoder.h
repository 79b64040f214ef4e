#pragma once
// One CiA 406 encoder on the CAN bus as the engine's SensorInput (a line encoder on a
// measuring roller, a slider's scale): the position value 0x6004 of the TPDO of the last SYNC,
// scaled by counts per unit.
//
// Threading contract: read() from the engine thread only; it touches the node's atomics
// (NodeShared) only - no lock, no allocation, no Qt. The master thread does the CAN I/O and
// the supervision (heartbeat, SYNCs left unanswered): a node in fault reads not valid.
#include "core/devices/device_interfaces.h"
#include "devices/canopen/node_shared.h"

namespace cutcell::canopen {

class CanOpenEncoder final : public SensorInput {
  public:
    CanOpenEncoder(int node, double countsPerUnit, NodeShared& shared)
        : node_(node), countsPerUnit_(countsPerUnit), shared_(shared) {}

    SensorReading read(double now_s) override;
    // The engine's cycle count (the SYNC-posting drive's write_seq) to date the readings by
    // (age_cycles); null: every reading is taken as on time.
    void setCycleClock(const std::atomic<std::uint64_t>* writeSeq) { clock_ = writeSeq; }
    int node() const { return node_; }
    double countsPerUnit() const { return countsPerUnit_; }

  private:
    int node_;
    double countsPerUnit_;
    NodeShared& shared_;
    const std::atomic<std::uint64_t>* clock_ = nullptr;
};

} // namespace cutcell::canopen
