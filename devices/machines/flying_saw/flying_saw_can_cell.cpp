// The flying saw's CAN cell: four CSP drives (carriage, turntable, two feeds) and the line's
// CiA 406 encoder, which reads the pipe line's travel as the measuring roller does.
#include "core/machines/flying_saw/flying_saw_program.h"
#include "core/machines/flying_saw/pipe_line_sim.h"
#include "devices/machines/can_cell_machine.h"

#include <cmath>
#include <memory>

namespace cutcell {

bool fillFlyingSawCanCell(CanCellBuilder& b, std::string* error) {
    const auto* saw = b.job.machine_spec.as<FlyingSawSpec>();
    if (!saw) {
        if (error) *error = "the job holds no flying-saw section";
        return false;
    }
    for (int a = 0; a < b.cell.axis_count; ++a) {
        canopen::DriveNodeConfig d = b.driveNode(a, sawAxisGains(), sawAxisPlant());
        d.start_position_rad = b.startOf(a);
        // 20 mm (or deg) of following error before the drive faults itself: the engine's
        // limit (engine.following_error_limit_mm) acts first.
        d.following_error_window_counts = static_cast<std::uint32_t>(
            std::lround(20 * b.job.devices.counts_per_unit[static_cast<size_t>(a)]));
        b.cell.sim_drives.push_back(d);
    }
    b.cell.fastest_linear_mm_s = saw->carriage.max_speed_mm_s;
    // The line encoder: the pipe line's travel as the measuring roller reads it (speed profile
    // with ramps, steps and noise, slip, the roller's resolution), counted by a CiA 406 encoder
    // of that resolution.
    PipeLineConfig lc;
    lc.speed_mm_s = saw->lineSpeedMmS();
    lc.resolution_mm = saw->encoderResolutionMm();
    lc.sim = saw->line_sim;
    lc.duration_s = 3600;
    auto line = std::make_shared<PipeLineSim>(lc);
    // On the SYNC clock, as the simulated drives move (encoder_node.h): the line advances one
    // period per SYNC, however late the SYNCs come on a loaded host.
    b.addEncoder(0, 1.0 / lc.resolution_mm, [line](double t) { return line->read(t).position; });
    b.cell.sim_encoders.back().sync_period_s = b.period_s;
    return true;
}

} // namespace cutcell
