#pragma once
// Bus load of the cyclic CANopen traffic on a classic CAN bus, from the frame format with
// worst-case bit stuffing (Davis, Burns, Bril, Lukkien 2007, eq. 2 for 11-bit identifiers):
//   bits(n) = 8n + 47 + floor((34 + 8n - 1) / 4)   for n data bytes
// (34 + 8n bits from SOF to CRC are subject to stuffing, 13 bits of delimiters, ACK, EOF and
// inter-frame space are not). 8 bytes: 135 bit; 0 bytes (SYNC): 55 bit.
#include <string>

namespace cutcell::canopen {

int worstCaseFrameBits(int dataBytes);

struct BusLoadInput {
    double period_s = 0.001; // SYNC / engine cycle
    double bitrate_bps = 1e6;
    int nodes = 6;
    int rpdo_bytes = 6;              // per node per cycle
    int tpdo_bytes = 8;              // per node per cycle
    double heartbeat_period_s = 0.1; // each node's heartbeat (1 byte), 0 = none
    int other_heartbeats = 0;        // producers beside the nodes (the master's own)
    double limit = 0.8;              // highest admissible load
};

struct BusLoad {
    int frames_per_cycle = 0;  // cyclic frames (RPDOs, TPDOs, SYNC)
    double bits_per_cycle = 0; // cyclic + heartbeats averaged over the cycle
    double load = 0;           // fraction of the bit rate
    double min_period_s = 0;   // shortest period within the limit
    bool ok = false;
    std::string message; // the figures; says what to change when !ok
};

BusLoad computeBusLoad(const BusLoadInput& in);

} // namespace cutcell::canopen
