#pragma once
// Motion-engine settings for CANopen drives. The engine's defaults suit exact in-process
// drives; over a bus positions travel as whole encoder counts and the feedback of a cycle is
// the TPDO of an earlier SYNC (a few cycles late on a busy host: virtualcan goes through TCP).
// The machine's own settings (its simulated rig's configure()) stay where they are coarser.
#include "core/engine/motion_engine.h"
#include "core/job/job.h"
#include "devices/canopen/canopen_master.h"

#include <algorithm>

namespace cutcell::canopen {

// For the drives of a master configuration (rotary axes in rad, linear axes in mm).
inline void tuneEngineForCan(EngineConfig& config, const CanOpenMasterConfig& mc,
                             double homeSpeedDegS, double period_s) {
    config.period_s = period_s;
    // A set-point written after SYNC k is acted on at SYNC k + 1 and seen in the TPDO of k + 2.
    config.setpoint_lead_s = 2 * period_s;
    double count = 0; // axis units per count, the coarsest drive
    bool linear = false;
    for (const MasterNodeConfig& n : mc.nodes) {
        if (n.encoder) continue;
        count = std::max(count, n.linear ? 1.0 / n.counts_per_unit
                                         : 1.0 / (n.counts_per_unit * 180.0 / kPi));
        linear = linear || n.linear;
    }
    // In position: within a few counts, moving less than a few counts per cycle.
    config.in_position_window = std::max(config.in_position_window, 3 * count);
    config.in_position_velocity = std::max(config.in_position_velocity, 3 * count / period_s);
    // Frozen feedback: unchanged while the set-point moved what the home speed covers in 20
    // cycles (a stopped encoder is still caught within 20 cycles at full speed).
    config.frozen_feedback_travel =
        std::max({config.frozen_feedback_travel, 20 * period_s * deg2rad(homeSpeedDegS),
                  linear ? 20 * period_s * config.spec.home_speed_mm_s : 0.0});
}

} // namespace cutcell::canopen
