#pragma once
// Planning a flying-saw job: the five periods from the carriage's limits and the line speed,
// the saw's cycle and cam table, and the refusals with their figures (a length too short for
// the cycle at this line speed, with the shortest possible; a stroke too short for the sync +
// cut; a line speed the carriage cannot reach).
#include "core/machines/flying_saw/flying_saw_spec.h"
#include "core/machines/flying_saw/saw_cycle.h"
#include "core/machines/flying_saw/tracking_profile.h"

#include <string>

namespace cutcell {

struct FlyingSawPlan {
    bool ok = false;
    std::string problem;    // when !ok: key, value, unit and the limit
    std::string problemKey; // the job key the problem names
    double line_speed_mm_s = 0;
    double line_speed_max_mm_s = 0; // with the wander and steps of the simulated line
    ForwardStroke forward;
    SawCycle saw;
    // The seed's period times at the nominal line speed (s): T1 = BC, T2 = CE (settle + cut),
    // T3 = EF, T4 = FG = T6 = HI, T5 = GH; k = reverse speed / line speed.
    double T1 = 0, T2 = 0, T3 = 0, T4 = 0, T5 = 0, T6 = 0, k = 0;
    double stroke_needed_mm = 0;          // at the highest line speed
    double forward_travel_mm = 0;         // at the nominal line speed
    ReverseProfile reverse;               // at the highest line speed's forward travel
    ReverseProfile nominal_reverse;       // at the nominal line speed's forward travel
    double shortest_length_mm = 0;        // shortest piece at the highest line speed
    double cycle_time_s = 0;              // sync-in to back at rest (nominal speed)
    double cam_max_between_points_mm = 0; // blade tip off the outline between table points
    // Peak radial-feed acceleration the cam asks for at the turntable's full speed (the feed
    // follows corners: d2 feed / d theta2 * omega^2; a sharp inner corner makes it large).
    double feed_accel_peak_mm_s2 = 0;
};

// The tube's outer outline in the cut plane.
TubeOutline outerOutline(const FlyingSawSpec& spec);

FlyingSawPlan planFlyingSaw(const FlyingSawSpec& spec);

} // namespace cutcell
