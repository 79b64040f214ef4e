#pragma once
// Lead-in and lead-out of the profile cutter's closed cut (issue 24), on the developed pipe
// surface (X, R_w A) like the kerf offset (profile_kerf.h).
//
//  - lead-in (process.lead_in): the torch pierces on the scrap side and runs onto the cut's
//    start point: "line" = straight, square to the cut, length_mm long; "arc" = a quarter
//    circle of arc length length_mm (radius 2 L / pi) joining the cut tangentially.
//  - lead-out (process.lead_out): after the closed cut the torch runs on along the cut for
//    overlap_mm past the start, then leaves to the scrap side by a line (square to the cut) or
//    a quarter arc of length_mm.
//  - the torch height Z (a simulated axis: this machine has no Z drive): the pierce at the
//    pierce height, the pierce delay, then down to the cut height (chart or override).
//
// Every lead point lies on the scrap side, at least half the kerf from the part's edge; a
// lead too long for the cut (it would reach the part's edge across the hole) is refused with
// the longest length that fits.
#include "core/job/job.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/process/process_spec_data.h"

#include <string>
#include <vector>

namespace cutcell {

struct ProfileLeads {
    bool used = false; // a lead-in or lead-out is asked for (the G-code then writes Z)
    LeadSpec in, out;  // as the job asks
    // The lead-in from the pierce point up to (not including) the cut's first point; the
    // lead-out after the cut's closing point (the first point one turn later) to its end.
    std::vector<ProfilePoint> lead_in, lead_out;
    double pierce_height_mm = 0, cut_height_mm = 0; // Z over the pipe surface
    double pierce_delay_s = 0; // the chart's pierce delay, else profile_cutter.pierce_s
    std::string problem;       // the leads cannot be made: why (key, value, unit, limit)
    std::string problem_key;   // the job key it is about
};

// The leads of the torch path `cut` (computeProfileCut) whose part edge is `edge` (the same
// grid, computeProfileEdge). Unused (and empty) when the job asks for none.
ProfileLeads computeProfileLeads(const Job& job, const ProfileCut& cut, const ProfileCut& edge);
ProfileLeads computeProfileLeads(const Job& job, const ProfileCut& cut);

// Whether the developed point (x_mm, a_deg) lies on the scrap side of the part's edge `edge`
// (inside the hole; beyond the branch end, larger X), and its developed distance to the edge.
bool profileOnScrapSide(const ProfileCut& edge, double x_mm, double a_deg);
double profileDistanceToEdge(const ProfileCut& edge, double x_mm, double a_deg);

// Empty when every lead point lies on the carriage (0 .. profile_cutter.x_travel_mm).
std::string leadTravelProblem(const Job& job, const ProfileLeads& leads);

} // namespace cutcell
