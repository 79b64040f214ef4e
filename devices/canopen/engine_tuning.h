#pragma once
// Motion-engine settings for CANopen drives. The engine's defaults suit exact in-process
// drives; over a bus positions travel as whole encoder counts and the feedback of a cycle is
// the TPDO of an earlier SYNC (a few cycles late on a busy host: virtualcan goes through TCP).
#include "core/engine/motion_engine.h"
#include "core/job/job.h"

#include <algorithm>

namespace cutcell::canopen {

inline void tuneEngineForCan(EngineConfig& config, const Job& job, double period_s) {
    config.period_s = period_s;
    // A set-point written after SYNC k is acted on at SYNC k + 1 and seen in the TPDO of k + 2.
    config.setpoint_lead_s = 2 * period_s;
    double count = 0; // rad per count, the coarsest axis (all axes of the pipe robot are rotary)
    for (double c : job.devices.counts_per_unit)
        count = std::max(count, 1.0 / (c * 180.0 / kPi));
    // In position: within a few counts, moving less than a few counts per cycle.
    config.in_position_window = 3 * count;
    config.in_position_velocity = 3 * count / period_s;
    // Frozen feedback: unchanged while the set-point moved what the home speed covers in 20
    // cycles (a stopped encoder is still caught within 20 cycles at full speed).
    config.frozen_feedback_travel = std::max(config.frozen_feedback_travel,
                                             20 * period_s * deg2rad(job.engine.home_speed_deg_s));
}

} // namespace cutcell::canopen
