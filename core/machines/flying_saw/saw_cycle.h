#pragma once
// The saw's work while the carriage rides with the pipe (seed 003 section 3), in time from the
// moment the carriage is in sync (point C): settle (C -> D), fast radial feed to just before
// the outline, slow feed through the wall, the turntable's half turn with both blades'
// radial feeds on the cam table of the turntable angle, then the retract. Both blades stand
// half a turn apart; the outline is centrally symmetric, so one table serves both.
//
// Feed = radial infeed from the retracted position, where the blade tip stands at
// retract_radius from the pipe axis; tip radius = retract_radius - feed. The cam puts the
// tip on the cut outline (the tube's outline moved inward by wall + overcut: through the wall)
// at every table point: feed(theta) = retract_radius - rho_cut(psi_A - theta), theta the
// turntable angle from the start of the turn (blade 1 at the outline's corner A, turning
// clockwise A -> B -> C as in the seed's Fig. 7).
#include "core/engine/cam_table.h"
#include "core/machines/flying_saw/tracking_profile.h"
#include "core/machines/flying_saw/tube_outline.h"

#include <string>

namespace cutcell {

struct SawSettings {
    double settle_s = 0.1;          // C -> D: stabilisation in sync before the saw moves
    double fast_feed_mm_s = 150;    // radial feed speed in air
    double slow_feed_mm_s = 40;     // through the wall
    double approach_gap_mm = 2;     // fast feed stops this far outside the outline
    double overcut_mm = 1;          // the tip goes this far past the bore
    double clearance_mm = 5;        // retracted tip outside the outline's largest radius
    double retract_mm_s = 400;      // radial retract speed
    double turntable_deg_s = 180;   // turntable speed during the half turn
    double turntable_deg_s2 = 3600; // its acceleration limit
    int table_points = 900;         // cam table intervals per 180 deg (the seed's 900)
};

// A cam table of the cut outline over the half turn (count = points + 1, period pi).
CamTable feedCamTable(const TubeOutline& outer, const TubeOutline& cut, double retractRadius,
                      int points);

struct SawCycle {
    TubeOutline outer, cut;
    double retract_radius = 0;
    CamTable cam;
    double t_settle = 0, t_fast = 0, t_slow = 0, t_retract = 0;
    double feed_fast_end = 0; // feed where the fast feed ends (just outside the outline)
    double feed_start = 0;    // cam(0): tip on the cut outline at the corner
    ReverseProfile turn;      // theta(t) over the half turn (a cosine-ramp move of pi)

    double duration() const { return t_settle + t_fast + t_slow + turn.duration() + t_retract; }
    // Turntable angle (rad, 0 .. pi) and feed (mm) at time tau after sync.
    void at(double tau, double* theta, double* feed) const;
    // The blade is in the wall (slow feed or half turn).
    bool cutting(double tau) const;
    // When the half turn starts and ends (after sync).
    double turnStart() const { return t_settle + t_fast + t_slow; }
    double turnEnd() const { return turnStart() + turn.duration(); }
};

// Empty and the cycle, or the reason it cannot be built (outline too small, ...).
std::string buildSawCycle(const TubeOutline& outer, double wall_mm, const SawSettings& s,
                          SawCycle* out);

} // namespace cutcell
