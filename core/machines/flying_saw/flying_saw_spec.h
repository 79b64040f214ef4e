#pragma once
// The flying saw's section of a job (its own struct in Job::machine_spec; see
// core/job/machine_spec.h). Units in the names; the JSON keys are the same (README).
#include "core/job/machine_spec.h"
#include "core/machines/flying_saw/saw_cycle.h"
#include "core/machines/flying_saw/tracking_profile.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace cutcell {

enum class TubeShape { Round, Rectangular };

struct PieceOrder {
    double length_mm = 6000;
    int count = 1;
};

struct LineSimSpec {               // the simulated line (simulate, run, bench)
    double wander_fraction = 0.02; // +- speed wander (sinusoidal)
    double wander_hz = 0.1;
    double step_fraction = 0.01; // +- steps of the speed
    double step_interval_s = 15; // mean time between steps
    double step_ramp_s = 0.2;    // a step takes this long (cosine ramp)
    double noise_mm = 0;         // uniform noise on the reading
    double slip_fraction = 0;    // the roller reads this fraction short
    std::uint32_t seed = 1;
};

struct FlyingSawSpec : MachineSpecOf<FlyingSawSpec> {
    // tube
    TubeShape shape = TubeShape::Rectangular;
    double diameter_mm = 60; // round
    double width_mm = 60;    // rectangular: a (across)
    double height_mm = 60;   // rectangular: b (up)
    double corner_radius_mm = 4;
    double wall_mm = 2;
    // line
    double line_speed_m_min = 60;
    // pieces: the queue (lengths may change while running: from the next piece)
    std::vector<PieceOrder> queue{{6000, 200}};
    double tolerance_mm = 1; // +- on the length (Cpk)
    // MC_GearInPos: the master position (mm of the line encoder) of the first (head) cut;
    // NaN (absent in the file) = the master at start + the sync-in span + 50 mm.
    double first_sync_master_mm = NAN;
    // carriage
    double stroke_mm = 2500;
    CarriageLimits carriage{3000, 10000, 200000};
    double wait_position_mm = 0;
    // saw
    SawSettings saw;
    double blade_diameter_mm = 400;
    double blade_kerf_mm = 3;
    double blade_rpm = 3000;
    // measuring roller -> encoder resolution pi D / pulses
    int roller_pulses_per_rev = 8000;
    double roller_diameter_mm = 127.32395447351627; // 400 mm circumference: 0.05 mm/pulse
    double filter_alpha = 0.2;
    // length gauge after the saw: corrects the encoder's scale from the measured pieces
    bool gauge_enabled = true;
    int gauge_delay_pieces = 1;
    double gauge_noise_mm = 0.02;
    double gauge_gain = 0.5;
    LineSimSpec line_sim;

    double lineSpeedMmS() const { return line_speed_m_min * 1000.0 / 60.0; }
    double encoderResolutionMm() const;
    int pieceCount() const;
};

} // namespace cutcell
