#pragma once
// G-code for a LinuxCNC profile cutter with an X (linear, mm) and an A (rotary, deg) axis.
//
//  - G21 G90, the job's parameters as comments, a rapid to the start, torch on (M3 S1, the torch
//    wired as spindle), a pierce dwell, then one G1 per step of the seed's grid;
//  - feed in inverse time (G93): each move's F is 60 v / ds with ds = sqrt(dX^2 + (R_w dA)^2)
//    on the developed surface, so the torch moves over the pipe at the cutting speed v whatever
//    the mix of X and A (LinuxCNC's G94 feed would apply to X alone on mixed moves);
//  - G94, torch off (M5), M2.
// Coordinates have 4 decimals (0.0001 mm / deg); F is computed from the written values.
//
// With a lead-in or lead-out (profile_lead.h) the torch height is a Z axis (simulated: the
// machine has no Z drive; Z = height over the pipe surface, mm): a rapid to the pierce point on
// the scrap side, G0 Z to the pierce height, torch on, G4 P the pierce delay, G1 Z down to the
// cut height, then the lead-in, the cut and the lead-out, each after a comment line naming it,
// torch off and G0 Z back to the pierce height. Without leads the program has no Z word and is
// the same as before the leads, byte for byte.
#include "core/job/job.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/profile_lead.h"

#include <string>

namespace cutcell {

struct GcodeStats {
    size_t moves = 0;     // G1 blocks
    double length_mm = 0; // developed length of the written moves
    double time_s = 0;    // sum of the inverse-time durations
};

std::string profileGcode(const Job& job, const ProfileCut& cut, GcodeStats* stats = nullptr);
// The moves of the stats count the lead moves too.
std::string profileGcode(const Job& job, const ProfileCut& cut, const ProfileLeads& leads,
                         GcodeStats* stats = nullptr);

} // namespace cutcell
