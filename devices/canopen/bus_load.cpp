#include "devices/canopen/bus_load.h"
#include "core/common/c_format.h"

#include <cmath>
#include <cstdio>

namespace cutcell::canopen {

int worstCaseFrameBits(int n) {
    return 8 * n + 47 + (34 + 8 * n - 1) / 4;
}

BusLoad computeBusLoad(const BusLoadInput& in) {
    BusLoad r;
    const int rpdo = worstCaseFrameBits(in.rpdo_bytes);
    const int tpdo = worstCaseFrameBits(in.tpdo_bytes);
    const int sync = worstCaseFrameBits(0);
    const int heartbeat = worstCaseFrameBits(1);
    r.frames_per_cycle = 2 * in.nodes + 1;
    const double cyclic = in.nodes * (rpdo + tpdo) + sync;
    // Heartbeats are not per cycle: their bits per second, then per cycle.
    const double heartbeatBitsPerS =
        in.heartbeat_period_s > 0
            ? (in.nodes + in.other_heartbeats) * heartbeat / in.heartbeat_period_s
            : 0;
    r.bits_per_cycle = cyclic + heartbeatBitsPerS * in.period_s;
    r.load = r.bits_per_cycle / (in.bitrate_bps * in.period_s);
    // load(T) = cyclic / (R T) + hb / R <= limit  ->  T >= cyclic / (R limit - hb)
    const double spare = in.bitrate_bps * in.limit - heartbeatBitsPerS;
    r.min_period_s = spare > 0 ? cyclic / spare : INFINITY;
    r.ok = r.load <= in.limit;
    // Templates the GUI translates (tools/core_messages.py); the advice is rounded up to 0.1 ms
    // so that following it passes.
    r.message = messageC(
        "cycle %.3f ms needs %d frames (%d RPDO x %d bit + %d TPDO x %d bit + SYNC %d bit) "
        "+ heartbeats %.1f bit = %.1f bit = %.1f %% of %.0f kbit/s; the limit is %.0f %%",
        in.period_s * 1e3, r.frames_per_cycle, in.nodes, rpdo, in.nodes, tpdo, sync,
        heartbeatBitsPerS * in.period_s, r.bits_per_cycle, r.load * 100, in.bitrate_bps / 1e3,
        in.limit * 100);
    if (!r.ok)
        r.message = messageC("%s; use a period >= %.1f ms", r.message.c_str(),
                             std::ceil(r.min_period_s * 1e4 - 1e-9) / 10);
    return r;
}

} // namespace cutcell::canopen
